"""Headless Chromium, used to print handouts to PDF and (in the tests) to load them.

Chromium is an optional system program (Debian package ``chromium``); nothing else needs it.
Every run gets a fresh profile folder and the flags that keep a headless browser from
reaching the network on its own (no background networking, component updates, sync or QUIC).
"""
from __future__ import annotations

import os
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
