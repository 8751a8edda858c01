//! A small static file server for dist/, used by `serve` and the browser tests.
//!
//! One thread per connection, on the standard library. The `tiny_http` pool
//! used before could leave a new connection queued behind threads that each
//! waited on one of the browser's idle keep-alive connections; a host page's
//! load then waited out the tests' four-minute page timeout.

use std::{
    io::{BufRead, BufReader, Write},
    net::{SocketAddr, TcpListener, TcpStream},
    path::{Component, Path, PathBuf},
    time::Duration,
};

use anyhow::Context as _;

/// How long a kept-alive connection may wait for its next request.
const IDLE: Duration = Duration::from_secs(30);

/// The longest request head read; longer ones are refused.
const MAX_HEAD: usize = 16 * 1024;

/// Serves `dist` on 127.0.0.1:`port` until the process is stopped.
pub fn serve_forever(dist: &Path, port: u16) -> anyhow::Result<()> {
    let listener = bind(port)?;
    println!("Edgewise is served at http://127.0.0.1:{port}/ (Ctrl+C stops)");
    accept(&listener, dist);
    Ok(())
}

/// Serves `dist` on a free port in a background thread; returns the address.
pub fn serve_in_background(dist: &Path) -> anyhow::Result<SocketAddr> {
    let listener = bind(0)?;
    let addr = listener
        .local_addr()
        .context("the test server has no address")?;
    let dist = dist.to_path_buf();
    std::thread::spawn(move || accept(&listener, &dist));
    Ok(addr)
}

fn bind(port: u16) -> anyhow::Result<TcpListener> {
    TcpListener::bind(("127.0.0.1", port))
        .with_context(|| format!("cannot listen on 127.0.0.1:{port}"))
}

fn accept(listener: &TcpListener, dist: &Path) {
    for stream in listener.incoming().flatten() {
        let dist = dist.to_path_buf();
        std::thread::spawn(move || serve_connection(stream, &dist));
    }
}

/// Answers the requests of one connection in turn until the client closes
/// it, asks to, or stays idle past [`IDLE`].
fn serve_connection(stream: TcpStream, dist: &Path) {
    stream.set_read_timeout(Some(IDLE)).ok();
    let Ok(mut writer) = stream.try_clone() else {
        return;
    };
    let mut reader = BufReader::new(stream);
    while let Some(request) = read_request(&mut reader) {
        // A client that hung up is not our problem.
        if respond(&mut writer, &request, dist).is_err() || !request.keep_alive {
            break;
        }
    }
}

/// What the server reads of a request: it serves files, so no body.
struct Request {
    method: String,
    target: String,
    accepts_gzip: bool,
    keep_alive: bool,
}

impl Request {
    /// Whether the method is one a file server answers (GET or HEAD).
    fn reads_a_file(&self) -> bool {
        self.method == "GET" || self.method == "HEAD"
    }
}

/// Reads one request's head; `None` at the end of the stream, after
/// [`IDLE`], or for a head that is not HTTP or is longer than [`MAX_HEAD`].
fn read_request(reader: &mut impl BufRead) -> Option<Request> {
    let mut line = String::new();
    let mut read = read_line_within(reader, &mut line, MAX_HEAD)?;
    let mut words = line.split_whitespace();
    let (method, target, version) = (words.next()?, words.next()?, words.next()?);
    let mut request = Request {
        method: method.to_owned(),
        target: target.to_owned(),
        accepts_gzip: false,
        // HTTP/1.1 keeps the connection unless told otherwise; 1.0 closes it.
        keep_alive: version == "HTTP/1.1",
    };
    loop {
        line.clear();
        read += read_line_within(reader, &mut line, MAX_HEAD - read)?;
        let header = line.trim_end();
        if header.is_empty() {
            // A body is never read, so the connection cannot carry on.
            if !request.reads_a_file() {
                request.keep_alive = false;
            }
            return Some(request);
        }
        let (name, value) = header.split_once(':')?;
        let value = value.trim().to_ascii_lowercase();
        if name.eq_ignore_ascii_case("Accept-Encoding") {
            request.accepts_gzip = value.contains("gzip");
        } else if name.eq_ignore_ascii_case("Connection") {
            request.keep_alive = match value.as_str() {
                "close" => false,
                "keep-alive" => true,
                _ => request.keep_alive,
            };
        }
    }
}

/// Reads one line of at most `limit` bytes into `line`, returning its
/// length (0 at the end of the stream); `None` on an error or timeout, and
/// for a longer line, which is not read whole: a head with no line break
/// must not fill the memory.
fn read_line_within(reader: &mut impl BufRead, line: &mut String, limit: usize) -> Option<usize> {
    let read = std::io::Read::take(&mut *reader, limit as u64 + 1)
        .read_line(line)
        .ok()?;
    (read <= limit).then_some(read)
}

/// Writes the answer to `request`: the file, its precompressed copy where
/// the client takes gzip and the build made one, or an error status.
fn respond(writer: &mut impl Write, request: &Request, dist: &Path) -> std::io::Result<()> {
    if !request.reads_a_file() {
        return write_response(
            writer,
            request,
            "405 Method Not Allowed",
            &[],
            b"GET or HEAD only",
        );
    }
    let Some(path) = resolve(dist, &request.target) else {
        return write_response(writer, request, "404 Not Found", &[], b"not found");
    };
    let gzipped = request
        .accepts_gzip
        .then(|| std::fs::read(gzipped_name(&path)).ok())
        .flatten();
    let encoded = gzipped.is_some();
    let Ok(body) = gzipped.map_or_else(|| std::fs::read(&path), Ok) else {
        return write_response(writer, request, "404 Not Found", &[], b"not found");
    };
    let mut headers = vec![
        ("Content-Type", content_type(&path)),
        ("Cache-Control", "no-cache"),
        ("Vary", "Accept-Encoding"),
    ];
    if encoded {
        headers.push(("Content-Encoding", "gzip"));
    }
    write_response(writer, request, "200 OK", &headers, &body)
}

fn write_response(
    writer: &mut impl Write,
    request: &Request,
    status: &str,
    headers: &[(&str, &str)],
    body: &[u8],
) -> std::io::Result<()> {
    let mut head = format!("HTTP/1.1 {status}\r\nContent-Length: {}\r\n", body.len());
    if !headers.iter().any(|(name, _)| *name == "Content-Type") {
        head.push_str("Content-Type: text/plain; charset=utf-8\r\n");
    }
    for (name, value) in headers {
        head.push_str(&format!("{name}: {value}\r\n"));
    }
    let connection = if request.keep_alive {
        "keep-alive"
    } else {
        "close"
    };
    head.push_str(&format!("Connection: {connection}\r\n\r\n"));
    writer.write_all(head.as_bytes())?;
    if request.method != "HEAD" {
        writer.write_all(body)?;
    }
    writer.flush()
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

    /// A fresh folder `edgewise-serve-NAME-PID` holding `files`, served on
    /// a free port.
    fn serve_files(name: &str, files: &[(&str, &str)]) -> (PathBuf, SocketAddr) {
        let dist =
            std::env::temp_dir().join(format!("edgewise-serve-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dist).unwrap();
        for (file, contents) in files {
            std::fs::write(dist.join(file), contents).unwrap();
        }
        let addr = serve_in_background(&dist).unwrap();
        (dist, addr)
    }

    /// A raw HTTP/1.0 request; the whole response.
    fn get(addr: SocketAddr, path: &str, accept: &str) -> String {
        use std::io::{Read as _, Write as _};
        let mut stream = TcpStream::connect(addr).unwrap();
        write!(
            stream,
            "GET {path} HTTP/1.0\r\nAccept-Encoding: {accept}\r\n\r\n"
        )
        .unwrap();
        let mut response = Vec::new();
        stream.read_to_end(&mut response).unwrap();
        String::from_utf8_lossy(&response).into_owned()
    }

    /// Idle connections, as a browser keeps them open, never hold up
    /// another client's request.
    #[test]
    fn idle_connections_do_not_hold_up_a_new_one() {
        let (dist, addr) = serve_files("idle", &[("index.html", "page")]);
        let idle: Vec<_> = (0..16).map(|_| TcpStream::connect(addr).unwrap()).collect();
        let page = get(addr, "/", "identity");
        assert!(page.starts_with("HTTP/1.1 200 OK"), "{page}");
        assert!(page.ends_with("page"), "{page}");
        drop(idle);
        std::fs::remove_dir_all(&dist).ok();
    }

    /// An HTTP/1.1 connection serves request after request; a HEAD gets the
    /// headers alone, and other methods are refused.
    #[test]
    fn a_kept_alive_connection_answers_in_turn() {
        use std::io::{Read as _, Write as _};
        let (dist, addr) = serve_files("keep", &[("a.txt", "first"), ("b.txt", "second")]);
        let mut stream = TcpStream::connect(addr).unwrap();
        write!(
            stream,
            "GET /a.txt HTTP/1.1\r\nHost: x\r\n\r\n\
             HEAD /b.txt HTTP/1.1\r\nHost: x\r\n\r\n\
             POST /b.txt HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n"
        )
        .unwrap();
        let mut response = String::new();
        stream.read_to_string(&mut response).unwrap();
        let answers: Vec<&str> = response.split("HTTP/1.1 ").skip(1).collect();
        assert_eq!(answers.len(), 3, "{response}");
        assert!(answers[0].starts_with("200 OK"), "{response}");
        assert!(answers[0].contains("Connection: keep-alive"), "{response}");
        assert!(answers[0].ends_with("first"), "{response}");
        assert!(answers[1].contains("Content-Length: 6"), "{response}");
        assert!(
            answers[1].ends_with("\r\n\r\n"),
            "a HEAD has no body: {response}"
        );
        assert!(answers[2].starts_with("405"), "{response}");
        assert!(answers[2].contains("Connection: close"), "{response}");
        std::fs::remove_dir_all(&dist).ok();
    }

    /// A request head longer than [`MAX_HEAD`] gets the connection closed.
    #[test]
    fn an_endless_head_is_cut_off() {
        use std::io::{Read as _, Write as _};
        let (dist, addr) = serve_files("head", &[]);
        let mut stream = TcpStream::connect(addr).unwrap();
        write!(stream, "GET / HTTP/1.1\r\n").unwrap();
        let header = format!("X-Long: {}\r\n", "a".repeat(1024));
        // The server closes the connection partway; later writes may fail.
        for _ in 0..(2 * MAX_HEAD / header.len()) {
            if stream.write_all(header.as_bytes()).is_err() {
                break;
            }
        }
        let mut response = Vec::new();
        stream.read_to_end(&mut response).ok();
        assert!(
            response.is_empty(),
            "{}",
            String::from_utf8_lossy(&response)
        );
        std::fs::remove_dir_all(&dist).ok();
    }

    /// So is a head line with no line break, before it is read whole.
    #[test]
    fn an_endless_line_is_cut_off() {
        use std::io::{Read as _, Write as _};
        let (dist, addr) = serve_files("line", &[]);
        let mut stream = TcpStream::connect(addr).unwrap();
        let line = format!("GET /{}", "a".repeat(4 * MAX_HEAD));
        // The server closes the connection partway; the write may fail.
        stream.write_all(line.as_bytes()).ok();
        let mut response = Vec::new();
        stream.read_to_end(&mut response).ok();
        assert!(
            response.is_empty(),
            "{}",
            String::from_utf8_lossy(&response)
        );
        std::fs::remove_dir_all(&dist).ok();
    }

    #[test]
    fn the_precompressed_copy_goes_to_clients_that_take_gzip() {
        let (dist, addr) = serve_files("gz", &[("app.js", "plain"), ("app.js.gz", "GZIPPED")]);
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
