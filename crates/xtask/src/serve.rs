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
        let response = match resolve(dist, request.url()) {
            Some(path) => match std::fs::read(&path) {
                Ok(bytes) => tiny_http::Response::from_data(bytes)
                    .with_header(header("Content-Type", content_type(&path)))
                    .with_header(header("Cache-Control", "no-cache")),
                Err(_) => not_found(),
            },
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

fn content_type(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") => "text/javascript; charset=utf-8",
        Some("wasm") => "application/wasm",
        Some("css") => "text/css; charset=utf-8",
        Some("svg") => "image/svg+xml",
        Some("png") => "image/png",
        Some("json") => "application/json",
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
}
