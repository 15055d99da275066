"""Headless Chromium, used to print handouts to PDF and (in the tests) to load them.

Chromium is an optional system program (Debian package ``chromium``); nothing else needs it.
Every run gets a fresh profile folder and the flags that keep a headless browser from
reaching the network on its own (no background networking, component updates, sync or QUIC).
:class:`Session` drives one browser over the DevTools protocol on a pipe (real key presses and
clicks, screenshots, downloads): the tests work the interactive page with it.
"""
from __future__ import annotations

import base64
import json
import os
import select
import shutil
import subprocess
import tempfile
from pathlib import Path

from polygons.errors import PolygonsError

NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-extensions", "--disable-dev-shm-usage", "--hide-scrollbars",
         "--mute-audio")
TIMEOUT = 120


class BrowserError(PolygonsError):
    """Chromium is missing or failed."""


def find() -> str | None:
    """Path of a Chromium executable (``$POLYGONS_CHROMIUM`` first), or None."""
    env = os.environ.get("POLYGONS_CHROMIUM")
    if env:
        return env if shutil.which(env) or Path(env).is_file() else None
    for name in NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


def _require() -> str:
    exe = find()
    if exe is None:
        raise BrowserError("PDF output needs headless Chromium, which is not installed "
                           "(Debian: apt-get install chromium; or set POLYGONS_CHROMIUM)")
    return exe


def run(url_or_path, *args: str, timeout: int = TIMEOUT) -> subprocess.CompletedProcess:
    """Run headless Chromium on a local file with extra ``args``; a fresh profile each time."""
    exe = _require()
    target = url_or_path if str(url_or_path).startswith(("file:", "data:", "about:")) \
        else Path(url_or_path).resolve().as_uri()
    with tempfile.TemporaryDirectory(prefix="polygons-chromium-") as profile:
        cmd = [exe, *FLAGS, f"--user-data-dir={profile}", *args, target]
        try:
            return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout,
                                  cwd=profile)
        except subprocess.TimeoutExpired:
            raise BrowserError(f"Chromium did not finish within {timeout} s on "
                               f"{url_or_path}") from None


def print_pdf(html_path, pdf_path) -> Path:
    """Print a local HTML file to PDF with Chromium's own print engine (the @page rules)."""
    pdf_path = Path(pdf_path).resolve()
    pdf_path.parent.mkdir(parents=True, exist_ok=True)
    if pdf_path.exists():
        pdf_path.unlink()
    out = run(html_path, f"--print-to-pdf={pdf_path}", "--no-pdf-header-footer",
              "--run-all-compositor-stages-before-draw")
    if not pdf_path.exists() or pdf_path.stat().st_size == 0:
        last = (out.stderr.strip().splitlines() or ["no message"])[-1]
        raise BrowserError(f"Chromium did not write {pdf_path} (exit {out.returncode}: "
                           f"{last})")
    return pdf_path


def screenshot(html_path, png_path, width: int = 1000, height: int = 1400) -> Path:
    png_path = Path(png_path).resolve()
    if png_path.exists():
        png_path.unlink()
    run(html_path, f"--screenshot={png_path}", f"--window-size={width},{height}")
    if not png_path.exists():
        raise BrowserError(f"Chromium did not write {png_path}")
    return png_path


def dump_dom(html_path, budget_ms: int = 3000) -> subprocess.CompletedProcess:
    """The DOM after load (scripts run within ``budget_ms`` of virtual time), on stdout;
    console messages on stderr (``--enable-logging=stderr``)."""
    return run(html_path, "--dump-dom", f"--virtual-time-budget={budget_ms}",
               "--enable-logging=stderr", "--v=0")


# ---------------------------------------------------------------- a driven browser (DevTools)
KEYS = {"Tab": 9, "Enter": 13, "Escape": 27, " ": 32, "ArrowLeft": 37, "ArrowUp": 38,
        "ArrowRight": 39, "ArrowDown": 40, "Delete": 46, "Backspace": 8}


class Session:
    """Headless Chromium driven over the DevTools protocol on a pipe (``--remote-debugging-pipe``:
    commands on fd 3, replies on fd 4; no port, no network).  Real (trusted) key presses, so
    Tab moves the focus as a user's would; used by the tests to work the page keyboard-only::

        with Session(width=1400, height=1000) as s:
            s.open(path); s.press("Tab"); s.evaluate("document.activeElement.id")
    """

    def __init__(self, width: int = 1400, height: int = 1000, downloads=None,
                 timeout: float = 60.0):
        import fcntl                      # POSIX only, like the pipe itself
        exe = _require()
        self._profile = tempfile.TemporaryDirectory(prefix="polygons-chromium-")
        r_cmd, w_cmd = os.pipe()          # we write commands → Chromium reads fd 3
        r_out, w_out = os.pipe()          # Chromium writes fd 4 → we read replies
        # the child's ends moved above fd 10, so putting them on 3 and 4 clobbers neither
        hi_cmd = fcntl.fcntl(r_cmd, fcntl.F_DUPFD_CLOEXEC, 10)
        hi_out = fcntl.fcntl(w_out, fcntl.F_DUPFD_CLOEXEC, 10)

        def fds():                        # in the child: the pipes as fds 3 and 4
            os.dup2(hi_cmd, 3)
            os.dup2(hi_out, 4)
        cmd = [exe, *FLAGS, f"--user-data-dir={self._profile.name}",
               "--remote-debugging-pipe", f"--window-size={width},{height}", "about:blank"]
        self._proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL, preexec_fn=fds,
                                      close_fds=False)
        for fd in (hi_cmd, hi_out):
            os.close(fd)
        os.close(r_cmd)
        os.close(w_out)
        self._w, self._r = os.fdopen(w_cmd, "wb", buffering=0), os.fdopen(r_out, "rb")
        self._id, self._buf, self.events = 0, b"", []
        self.timeout = timeout
        try:
            target = self.call("Target.createTarget", url="about:blank")["targetId"]
            self.sid = self.call("Target.attachToTarget", targetId=target,
                                 flatten=True)["sessionId"]
            self.send("Page.enable")
            self.send("Runtime.enable")
            self.send("Emulation.setFocusEmulationEnabled", enabled=True)
            self.send("Emulation.setDeviceMetricsOverride", width=width, height=height,
                      deviceScaleFactor=1, mobile=False)
            if downloads is not None:
                self.downloads(downloads)
        except Exception:
            self.close()
            raise

    # -- protocol
    def _read(self) -> dict:
        while b"\0" not in self._buf:
            ready, _, _ = select.select([self._r], [], [], self.timeout)
            if not ready:
                raise BrowserError(f"Chromium did not answer within {self.timeout:g} s")
            chunk = os.read(self._r.fileno(), 1 << 16)
            if not chunk:
                raise BrowserError("Chromium closed the DevTools pipe")
            self._buf += chunk
        msg, self._buf = self._buf.split(b"\0", 1)
        return json.loads(msg)

    def call(self, method: str, session: bool = False, **params) -> dict:
        self._id += 1
        msg = {"id": self._id, "method": method, "params": params}
        if session:
            msg["sessionId"] = self.sid
        self._w.write(json.dumps(msg).encode() + b"\0")
        while True:
            reply = self._read()
            if reply.get("id") == self._id:
                if "error" in reply:
                    raise BrowserError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            self.events.append(reply)

    def send(self, method: str, **params) -> dict:
        """A command to the page (its session)."""
        return self.call(method, session=True, **params)

    def wait(self, method: str) -> dict:
        """The next event ``method`` (one already received counts)."""
        for i, ev in enumerate(self.events):
            if ev.get("method") == method:
                return self.events.pop(i)
        while True:
            ev = self._read()
            if ev.get("method") == method:
                return ev
            self.events.append(ev)

    # -- what a test does
    def downloads(self, folder) -> None:
        """Save what the page downloads into ``folder`` (under the names it suggests)."""
        self.call("Browser.setDownloadBehavior", behavior="allow",
                  downloadPath=str(Path(folder).resolve()))

    def open(self, path, fragment: str = "") -> None:
        url = Path(path).resolve().as_uri() + fragment
        self.events = [e for e in self.events if e.get("method") != "Page.loadEventFired"]
        self.send("Page.navigate", url=url)
        self.wait("Page.loadEventFired")

    def evaluate(self, expression: str):
        res = self.send("Runtime.evaluate", expression=expression, returnByValue=True,
                        awaitPromise=True)
        if "exceptionDetails" in res:
            raise BrowserError(f"script error: {res['exceptionDetails'].get('text')} "
                               f"{res['exceptionDetails'].get('exception', {}).get('description', '')}")
        return res.get("result", {}).get("value")

    def press(self, key: str, times: int = 1, shift: bool = False) -> None:
        """A real key press (down and up) of ``key``: 'Tab', 'Enter', 'ArrowLeft', 'n' ..."""
        code = KEYS.get(key, ord(key.upper()) if len(key) == 1 else 0)
        text = {"Enter": "\r", " ": " "}.get(key, key if len(key) == 1 else "")
        for _ in range(times):
            down = {"type": "keyDown" if text else "rawKeyDown", "key": key,
                    "windowsVirtualKeyCode": code, "modifiers": 8 if shift else 0,
                    "code": key if len(key) > 1 else f"Key{key.upper()}"}
            if text:
                down["text"] = text
            self.send("Input.dispatchKeyEvent", **down)
            self.send("Input.dispatchKeyEvent", type="keyUp", key=key,
                      windowsVirtualKeyCode=code, modifiers=8 if shift else 0,
                      code=down["code"])

    def click(self, x: float, y: float) -> None:
        """A real left click at (x, y) CSS px of the window."""
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                      clickCount=0 if kind == "mouseMoved" else 1)

    def screenshot(self, png_path, clip: dict | None = None) -> Path:
        """A PNG of the window, or of ``clip`` = {x, y, width, height} in page coordinates."""
        params = {"format": "png"}
        if clip:            # page coordinates (CSS px), beyond the window if need be
            params["clip"] = {**clip, "scale": 1}
            params["captureBeyondViewport"] = True
        data = self.send("Page.captureScreenshot", **params)["data"]
        png_path = Path(png_path)
        png_path.write_bytes(base64.b64decode(data))
        return png_path

    def close(self) -> None:
        try:
            if self._proc.poll() is None:
                try:
                    self.call("Browser.close")
                except Exception:
                    pass
                try:
                    self._proc.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    self._proc.kill()
                    self._proc.wait()
        finally:
            for f in (getattr(self, "_w", None), getattr(self, "_r", None)):
                if f is not None:
                    try:
                        f.close()
                    except OSError:
                        pass
            self._profile.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
