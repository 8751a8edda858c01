//! A small static file server for dist/, used by `serve` and the browser tests.

use std::{
    net::SocketAddr,
    path::{Component, Path, PathBuf},
};

use anyhow::Context as _;

/// Serves `dist` on 127.0.0.1:`port` until the process is stopped.
pub fn serve_forever(dist: &Path, port: u16) -> anyhow::Result<()> {
    let server = bind(port)?;
    println!("Edgewise is served at http://127.0.0.1:{port}/ (Ctrl+C stops)");
    handle_requests(&server, dist);
    Ok(())
}

/// Serves `dist` on a free port in a background thread; returns the address.
pub fn serve_in_background(dist: &Path) -> anyhow::Result<SocketAddr> {
    let server = bind(0)?;
    let addr = server
        .server_addr()
        .to_ip()
        .context("the test server has no IP address")?;
    let dist = dist.to_path_buf();
    std::thread::spawn(move || handle_requests(&server, &dist));
    Ok(addr)
}

fn bind(port: u16) -> anyhow::Result<tiny_http::Server> {
    tiny_http::Server::http(("127.0.0.1", port))
        .map_err(|err| anyhow::anyhow!("cannot listen on 127.0.0.1:{port}: {err}"))
}

fn handle_requests(server: &tiny_http::Server, dist: &Path) {
    for request in server.incoming_requests() {
        let accepts_gzip = request
            .headers()
            .iter()
            .any(|h| h.field.equiv("Accept-Encoding") && h.value.as_str().contains("gzip"));
        let response = match resolve(dist, request.url()) {
            Some(path) => {
                // The build's precompressed copy, where there is one.
                let gzipped = accepts_gzip
                    .then(|| std::fs::read(gzipped_name(&path)).ok())
                    .flatten();
                let encoded = gzipped.is_some();
                match gzipped.map_or_else(|| std::fs::read(&path), Ok) {
                    Ok(bytes) => {
                        let response = tiny_http::Response::from_data(bytes)
                            .with_header(header("Content-Type", content_type(&path)))
                            .with_header(header("Cache-Control", "no-cache"))
                            .with_header(header("Vary", "Accept-Encoding"));
                        if encoded {
                            response.with_header(header("Content-Encoding", "gzip"))
                        } else {
                            response
                        }
                    }
                    Err(_) => not_found(),
                }
            }
            None => not_found(),
        };
        // A client that hung up is not our problem.
        request.respond(response).ok();
    }
}

fn not_found() -> tiny_http::Response<std::io::Cursor<Vec<u8>>> {
    tiny_http::Response::from_string("not found")
        .with_status_code(404)
        .with_header(header("Content-Type", "text/plain; charset=utf-8"))
}

fn header(name: &str, value: &str) -> tiny_http::Header {
    tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes())
        .unwrap_or_else(|()| unreachable!("static header {name}: {value} is valid"))
}

/// Maps a request URL to a file under `dist`, refusing anything outside it.
fn resolve(dist: &Path, url: &str) -> Option<PathBuf> {
    let path = url.split(['?', '#']).next().unwrap_or("/");
    let relative = Path::new(path.trim_start_matches('/'));
    if relative
        .components()
        .any(|c| !matches!(c, Component::Normal(_)))
    {
        return None;
    }
    let mut file = dist.join(relative);
    if file.is_dir() {
        file = file.join("index.html");
    }
    file.is_file().then_some(file)
}

/// `NAME.gz` beside `NAME`.
fn gzipped_name(path: &Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(".gz");
    PathBuf::from(name)
}

fn content_type(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript; charset=utf-8",
        Some("wasm") => "application/wasm",
        Some("css") => "text/css; charset=utf-8",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("json") => "application/json",
        // The host pages' themes (reveal.js, MkDocs) bring their fonts.
        Some("woff2") => "font/woff2",
        Some("woff") => "font/woff",
        Some("ttf") => "font/ttf",
        Some("obj" | "wtb" | "htb" | "txt" | "alg" | "md") => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolve_stays_inside_dist() {
        let dist = std::env::temp_dir().join("edgewise-serve-test");
        std::fs::create_dir_all(dist.join("sub")).unwrap();
        std::fs::write(dist.join("index.html"), "x").unwrap();
        std::fs::write(dist.join("sub/a.js"), "x").unwrap();
        assert_eq!(resolve(&dist, "/"), Some(dist.join("index.html")));
        assert_eq!(
            resolve(&dist, "/?embed=1#m=abc"),
            Some(dist.join("index.html"))
        );
        assert_eq!(resolve(&dist, "/sub/a.js"), Some(dist.join("sub/a.js")));
        assert_eq!(resolve(&dist, "/../etc/passwd"), None);
        assert_eq!(resolve(&dist, "/sub/../../x"), None);
        assert_eq!(resolve(&dist, "/missing.js"), None);
    }

    #[test]
    fn wasm_is_served_as_wasm() {
        assert_eq!(content_type(Path::new("a_bg.wasm")), "application/wasm");
        assert_eq!(
            content_type(Path::new("a.js")),
            "text/javascript; charset=utf-8"
        );
    }

    /// A raw HTTP/1.0 request; the whole response.
    fn get(addr: SocketAddr, path: &str, accept: &str) -> String {
        use std::io::{Read as _, Write as _};
        let mut stream = std::net::TcpStream::connect(addr).unwrap();
        write!(
            stream,
            "GET {path} HTTP/1.0\r\nAccept-Encoding: {accept}\r\n\r\n"
        )
        .unwrap();
        let mut response = Vec::new();
        stream.read_to_end(&mut response).unwrap();
        String::from_utf8_lossy(&response).into_owned()
    }

    #[test]
    fn the_precompressed_copy_goes_to_clients_that_take_gzip() {
        let dist = std::env::temp_dir().join(format!("edgewise-serve-gz-{}", std::process::id()));
        std::fs::create_dir_all(&dist).unwrap();
        std::fs::write(dist.join("app.js"), "plain").unwrap();
        std::fs::write(dist.join("app.js.gz"), "GZIPPED").unwrap();
        let addr = serve_in_background(&dist).unwrap();
        let gzipped = get(addr, "/app.js", "gzip, deflate, br");
        assert!(
            gzipped
                .to_ascii_lowercase()
                .contains("content-encoding: gzip"),
            "{gzipped}"
        );
        assert!(gzipped.contains("text/javascript"), "{gzipped}");
        assert!(gzipped.ends_with("GZIPPED"), "{gzipped}");
        let plain = get(addr, "/app.js", "identity");
        assert!(
            !plain.to_ascii_lowercase().contains("content-encoding"),
            "{plain}"
        );
        assert!(plain.ends_with("plain"), "{plain}");
        std::fs::remove_dir_all(&dist).ok();
    }
}
