//! Just enough of the Chrome DevTools Protocol for the browser check: start
//! Chromium headless, open a tab, navigate, evaluate a script, take a
//! screenshot, and keep the events (console messages) each tab sends.
//!
//! The protocol is JSON over one WebSocket (`tungstenite`): a command
//! `{"id", "method", "params", "sessionId"}` gets a reply with the same
//! `id`; everything else that arrives meanwhile is an event, kept for the
//! tab (`sessionId`) it came from. A typed client (`headless_chrome`) cost
//! CI 90 s of compiling its generated protocol for the six methods used.

use std::io::{BufRead, BufReader};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex, mpsc};
use std::time::Duration;

use serde_json::{Value, json};
use tungstenite::protocol::WebSocketConfig;
use tungstenite::{Message, WebSocket};

/// How long any one step may take before the check gives up on the browser.
const PATIENCE: Duration = Duration::from_secs(60);

/// A running headless Chromium and the connection to it.
pub struct Chromium {
    child: Child,
    socket: WebSocket<TcpStream>,
    next_id: u64,
    /// Events not yet taken, each with its tab's session id.
    events: Vec<Value>,
    profile: PathBuf,
}

/// One tab: the target Chromium made and the session that talks to it.
pub struct Tab {
    target: String,
    session: String,
}

impl Chromium {
    /// Starts `chrome` headless with a window of `width` × `height` px and
    /// `flags`, and connects to it.
    pub fn start(
        chrome: &Path, (width, height): (u32, u32), flags: &[&str],
    ) -> Result<Chromium, String> {
        let profile = std::env::temp_dir()
            .join(format!("raystep-chromium-{}", std::process::id()));
        let mut child = Command::new(chrome)
            .args([
                "--headless",
                "--no-sandbox",
                "--remote-debugging-port=0",
                &format!("--window-size={width},{height}"),
                &format!("--user-data-dir={}", profile.display()),
            ])
            .args(flags)
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start {}: {e}", chrome.display()))?;

        // Chromium names its DevTools address on stderr; the rest of its
        // stderr is kept to explain a failed start.
        let stderr = child.stderr.take().expect("stderr is piped");
        let said: Arc<Mutex<Vec<String>>> = Arc::default();
        let (address, listening) = mpsc::channel();
        let lines = Arc::clone(&said);
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines() {
                let Ok(line) = line else { break };
                if let Some(url) = line.strip_prefix("DevTools listening on ") {
                    let _ = address.send(url.trim().to_string());
                }
                lines.lock().unwrap().push(line);
            }
        });
        let url = listening.recv_timeout(PATIENCE).map_err(|_| {
            let _ = child.kill();
            let said = said.lock().unwrap();
            let tail = said[said.len().saturating_sub(5)..].join("\n  ");
            if tail.is_empty() {
                "Chromium did not open its DevTools port, and said nothing"
                    .to_string()
            } else {
                format!(
                    "Chromium did not open its DevTools port; it said:\n  \
                     {tail}"
                )
            }
        })?;

        let host = url
            .strip_prefix("ws://")
            .and_then(|rest| rest.split('/').next())
            .ok_or_else(|| format!("unexpected DevTools address {url}"))?;
        let stream = TcpStream::connect(host)
            .and_then(|s| s.set_read_timeout(Some(PATIENCE)).map(|()| s))
            .map_err(|e| format!("{url}: {e}"))?;
        // A full-page screenshot is one message of several MB.
        let config = WebSocketConfig::default()
            .max_message_size(Some(1 << 30))
            .max_frame_size(Some(1 << 30));
        let (socket, _) = tungstenite::client::client_with_config(
            url.as_str(),
            stream,
            Some(config),
        )
        .map_err(|e| format!("{url}: {e}"))?;
        Ok(Chromium {
            child,
            socket,
            next_id: 1,
            events: Vec::new(),
            profile,
        })
    }

    /// Sends one command (to a tab, or to the browser when `tab` is
    /// `None`) and waits for its reply, keeping the events that come first.
    pub fn call(
        &mut self, tab: Option<&Tab>, method: &str, params: Value,
    ) -> Result<Value, String> {
        let id = self.next_id;
        self.next_id += 1;
        let mut command =
            json!({ "id": id, "method": method, "params": params });
        if let Some(tab) = tab {
            command["sessionId"] = tab.session.clone().into();
        }
        self.socket
            .send(Message::text(command.to_string()))
            .map_err(|e| format!("{method}: {e}"))?;
        loop {
            let mut message = self.read(method)?;
            if message["id"] == id {
                if let Some(error) = message.get("error") {
                    return Err(format!("{method}: {}", error["message"]));
                }
                return Ok(message["result"].take());
            }
            if message.get("method").is_some() {
                self.events.push(message);
            }
        }
    }

    /// Waits for the event `method` from `tab`.
    pub fn wait_for(&mut self, tab: &Tab, method: &str) -> Result<(), String> {
        let of_tab = |e: &Value| e["sessionId"] == tab.session.as_str();
        if self
            .events
            .iter()
            .any(|e| of_tab(e) && e["method"] == method)
        {
            return Ok(());
        }
        loop {
            let message = self.read(method)?;
            let found = of_tab(&message) && message["method"] == method;
            if message.get("method").is_some() {
                self.events.push(message);
            }
            if found {
                return Ok(());
            }
        }
    }

    /// Takes the events `tab` has sent so far.
    pub fn take_events(&mut self, tab: &Tab) -> Vec<Value> {
        let (mine, others) = std::mem::take(&mut self.events)
            .into_iter()
            .partition(|e| e["sessionId"] == tab.session.as_str());
        self.events = others;
        mine
    }

    /// Opens a blank tab and attaches to it.
    pub fn open_tab(&mut self) -> Result<Tab, String> {
        let made = self.call(
            None,
            "Target.createTarget",
            json!({ "url": "about:blank" }),
        )?;
        let target = made["targetId"].as_str().ok_or("no targetId")?;
        let attached = self.call(
            None,
            "Target.attachToTarget",
            json!({ "targetId": target, "flatten": true }),
        )?;
        let session = attached["sessionId"].as_str().ok_or("no sessionId")?;
        Ok(Tab {
            target: target.to_string(),
            session: session.to_string(),
        })
    }

    pub fn close_tab(&mut self, tab: Tab) -> Result<(), String> {
        self.call(
            None,
            "Target.closeTarget",
            json!({ "targetId": tab.target }),
        )?;
        self.take_events(&tab);
        Ok(())
    }

    /// Runs `script` in the tab, waits for its promise, and returns its
    /// value; a thrown exception is an error.
    pub fn evaluate(
        &mut self, tab: &Tab, script: &str,
    ) -> Result<Value, String> {
        let mut result = self.call(
            Some(tab),
            "Runtime.evaluate",
            json!({
                "expression": script,
                "awaitPromise": true,
                "returnByValue": true,
            }),
        )?;
        if let Some(details) = result.get("exceptionDetails") {
            let text = details["exception"]["description"]
                .as_str()
                .or(details["text"].as_str())
                .unwrap_or("an exception");
            return Err(format!("the script threw: {text}"));
        }
        Ok(result["result"]["value"].take())
    }

    fn read(&mut self, waiting_for: &str) -> Result<Value, String> {
        loop {
            let message = self.socket.read().map_err(|e| {
                format!("waiting for {waiting_for}: {e} (Chromium gone?)")
            })?;
            if let Message::Text(text) = message {
                return serde_json::from_str(text.as_str())
                    .map_err(|e| format!("waiting for {waiting_for}: {e}"));
            }
        }
    }
}

impl Drop for Chromium {
    fn drop(&mut self) {
        let close = json!({ "id": 0, "method": "Browser.close" });
        let _ = self.socket.send(Message::text(close.to_string()));
        for _ in 0..50 {
            if let Ok(Some(_)) = self.child.try_wait() {
                break;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = std::fs::remove_dir_all(&self.profile);
    }
}
