"""The pages in headless Chromium: the plots render, the console stays
clean, no page is wider than the window and none makes a network request
(plotly.js is the output folder's own plotly.min.js).

The browser is driven over the DevTools protocol on a pipe
(--remote-debugging-pipe: commands on fd 3, replies on fd 4, each message
JSON ended by a NUL byte), so no websocket library is needed. Requests the
browser makes for itself (updates, accounts) belong to no page session and
are not counted; every request of the report's own session is.
"""
from __future__ import annotations

import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import time
from pathlib import Path

import pytest

from sizing.engine.solve import solve
from sizing.io.catalog import Catalog, load_catalog
from sizing.io.requirements import load_requirements
from sizing.report.bundle import PLOTLY_FILE, plotly_js
from sizing.report.html import render

from ..conftest import CATALOGS, STUDIES

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
# where the first screen of each page is kept as a PNG for people to look at
# (CI keeps the folder as the run's artefact)
ARTIFACTS = Path(os.environ.get("SIZING_TEST_ARTIFACTS", Path(__file__).resolve().parents[2] / "test-artifacts"))


def _screenshot(dt, session, name: str) -> Path:
    """The page's first screen, as the reader sees it on opening it."""
    png = base64.b64decode(dt.send("Page.captureScreenshot", {"format": "png"}, session=session)["data"])
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    path = ARTIFACTS / f"{name}.png"
    path.write_bytes(png)
    return path


def _pipe_fds(read_fd, write_fd):
    """In the child: the browser's command pipe on fd 3, its replies on fd 4
    (moved above 10 first so that neither dup2 clobbers the other)."""
    a = fcntl.fcntl(read_fd, fcntl.F_DUPFD, 10)
    b = fcntl.fcntl(write_fd, fcntl.F_DUPFD, 10)
    os.dup2(a, 3)
    os.dup2(b, 4)


class DevTools:
    def __init__(self, user_data_dir):
        to_r, to_w = os.pipe()      # we write commands, the browser reads fd 3
        from_r, from_w = os.pipe()  # the browser writes fd 4, we read
        self.proc = subprocess.Popen(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--no-first-run", f"--user-data-dir={user_data_dir}",
             "--remote-debugging-pipe", "about:blank"],
            pass_fds=(to_r, from_w, 3, 4), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=lambda: _pipe_fds(to_r, from_w))
        os.close(to_r)
        os.close(from_w)
        self.w, self.r = to_w, from_r
        self.buffer = b""
        self.events: list[dict] = []
        self.next_id = 0

    def send(self, method, params=None, session=None, timeout=30.0):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.w, json.dumps(msg).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def wait_for(self, method, timeout=30.0):
        deadline = time.monotonic() + timeout
        while not any(e.get("method") == method for e in self.events):
            self.events.append(self._read(deadline))

    def _read(self, deadline) -> dict:
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.r], [], [], left)[0]:
                raise TimeoutError("no reply from chromium")
            chunk = os.read(self.r, 1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed the pipe")
            self.buffer += chunk
        raw, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(raw)

    def close(self):
        try:
            self.send("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        os.close(self.w)
        os.close(self.r)


@pytest.fixture(scope="module")
def report_file(tmp_path_factory):
    req, sha = load_requirements(STUDIES / "seed-requirements.toml")
    full = load_catalog(CATALOGS)
    cat = Catalog(folder=full.folder, stacks={"pi-p-056.90": full.stacks["pi-p-056.90"]},
                  fluids={"mil-prf-87257": full.fluids["mil-prf-87257"]},
                  seals={"ptfe-spring-energised": full.seals["ptfe-spring-energised"]},
                  amplifiers={"pi-e-481": full.amplifiers["pi-e-481"]},
                  dc_actuators=dict(full.dc_actuators), files=dict(full.files))
    out = solve(req, sha, cat)
    path = tmp_path_factory.mktemp("report") / "report.html"
    path.write_text(render(out.results, out.traces), encoding="utf-8")
    (path.parent / PLOTLY_FILE).write_text(plotly_js(), encoding="utf-8")     # the folder's one bundle
    return path


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")
def test_report_renders_offline_without_console_errors(report_file, tmp_path):
    dt = DevTools(tmp_path / "profile")
    try:
        target = dt.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = dt.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Network", "Log"):
            dt.send(f"{domain}.enable", session=session)
        dt.send("Page.navigate", {"url": report_file.as_uri()}, session=session)
        dt.wait_for("Page.loadEventFired")
        expr = ("Array.from(document.querySelectorAll('.plotly-graph-div'))"
                ".map(d => d.querySelectorAll('svg.main-svg').length)")
        counts = []
        for _ in range(50):      # plotly draws right after load; allow it a moment
            counts = dt.send("Runtime.evaluate", {"expression": expr, "returnByValue": True},
                             session=session)["result"]["value"]
            if counts and all(n > 0 for n in counts):
                break
            time.sleep(0.1)
        title = dt.send("Runtime.evaluate", {"expression": "document.title", "returnByValue": True},
                        session=session)["result"]["value"]
        wide = dt.send("Runtime.evaluate", {"expression": "document.documentElement.scrollWidth > window.innerWidth + 1",
                                            "returnByValue": True}, session=session)["result"]["value"]
        shot = _screenshot(dt, session, "solve")
    finally:
        dt.close()
    assert title == "sizing report"
    assert not wide, "the report is wider than the window"
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 10_000
    # every figure the file defines is drawn (Pareto front, traces, piezo vs DC, and the
    # force-path and thermal-budget figures)
    expected = report_file.read_text().count("Plotly.newPlot(")
    assert expected >= 3 and len(counts) == expected and all(n > 0 for n in counts), (counts, expected)
    mine = [e for e in dt.events if e.get("sessionId") == session]
    errors = [e for e in mine if e.get("method") == "Runtime.exceptionThrown"
              or (e.get("method") == "Runtime.consoleAPICalled" and e["params"]["type"] in ("error", "assert"))
              or (e.get("method") == "Log.entryAdded" and e["params"]["entry"]["level"] == "error")]
    assert not errors, errors
    requests = [e["params"]["request"]["url"] for e in mine if e.get("method") == "Network.requestWillBeSent"]
    external = [u for u in requests if not u.startswith(("file:", "data:", "about:", "blob:"))]
    assert not external, external
    assert any(u.startswith("file:") for u in requests)     # the network domain did see the page itself


def _page_errors(dt, session) -> list[dict]:
    mine = [e for e in dt.events if e.get("sessionId") == session]
    return [e for e in mine if e.get("method") == "Runtime.exceptionThrown"
            or (e.get("method") == "Runtime.consoleAPICalled" and e["params"]["type"] in ("error", "assert"))
            or (e.get("method") == "Log.entryAdded" and e["params"]["entry"]["level"] == "error")]


def _open_page(dt, path):
    """Open ``path`` in a new tab; returns its session, the plots drawn
    (svg count per plot div) and whether the page is wider than the window."""
    target = dt.send("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = dt.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    for domain in ("Page", "Runtime", "Log"):
        dt.send(f"{domain}.enable", session=session)
    dt.send("Page.navigate", {"url": path.as_uri()}, session=session)
    dt.wait_for("Page.loadEventFired")
    expr = "Array.from(document.querySelectorAll('.plotly-graph-div')).map(d => d.querySelectorAll('svg.main-svg').length)"
    counts = []
    for _ in range(50):      # plotly draws right after load; allow it a moment
        counts = dt.send("Runtime.evaluate", {"expression": expr, "returnByValue": True}, session=session)["result"]["value"]
        if counts and all(n > 0 for n in counts):
            break
        time.sleep(0.1)
    wide = dt.send("Runtime.evaluate", {"expression": "document.documentElement.scrollWidth > window.innerWidth + 1",
                                        "returnByValue": True}, session=session)["result"]["value"]
    return session, counts, wide


def _pages(tmp_path) -> dict:
    """One page of each kind, written by its own command into its own folder."""
    from ..conftest import FAST_REQUIREMENTS, run_cli
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 12").replace("max_simulated = 2", "max_simulated = 4"))
    camp = STUDIES / "campaigns" / "dc-motor"
    runs = sorted(str(p) for p in (camp / "runs").glob("*.csv"))
    commands = {
        "robust": ("robust", req, "--samples", "4", "--designs", "1", "--workers", "0", "--out", tmp_path / "robust"),
        "sweep": ("sweep", req, "--vary", "stroke=35mm..40mm:2", "--workers", "0", "--out", tmp_path / "sweep"),
        "diagnose": ("diagnose", camp, "--holdout", "steps_b", "--out", tmp_path / "diagnose"),
        "fit": ("fit", "dc-motor", *runs, "--rig", camp / "rig.toml", "--out", tmp_path / "fit" / "fit.toml"),
    }
    pages = {"robust": tmp_path / "robust" / "robust.html", "sweep": tmp_path / "sweep" / "sweep.html",
             "diagnose": tmp_path / "diagnose" / "diagnosis.html", "fit": tmp_path / "fit" / "fit.html"}
    for kind, args in commands.items():
        code, _, err = run_cli(*args, "--quiet") if kind in ("robust", "sweep") else run_cli(*args)
        assert code == 0, (kind, err)
    return pages


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")
def test_every_page_type_draws_without_errors_or_overflow(tmp_path):
    """robust, sweep, diagnose and fit pages: each loads its folder's
    plotly.min.js, draws every plot, logs no error and is no wider than the
    window."""
    pages = _pages(tmp_path)
    dt = DevTools(tmp_path / "profile")
    try:
        for kind, path in pages.items():
            assert (path.parent / PLOTLY_FILE).exists(), kind
            session, counts, wide = _open_page(dt, path)
            assert counts and all(n > 0 for n in counts), (kind, counts)
            assert not _page_errors(dt, session), (kind, _page_errors(dt, session))
            assert not wide, f"{kind} page is wider than the window"
            assert _screenshot(dt, session, kind).stat().st_size > 10_000, kind
    finally:
        dt.close()


# Every pair of texts a plot draws whose boxes overlap (more than a pixel
# each way), and the legend or colour bar over any text not its own: what a
# reader sees as overprinting. Tick labels of one axis count as texts, so
# rotated labels that collide are found too.
OVERPRINT_JS = r"""
(() => {
  const found = [];
  const box = e => e.getBoundingClientRect();
  const hit = (a, b) => Math.min(a.right, b.right) - Math.max(a.left, b.left) > 1 &&
                        Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top) > 1;
  document.querySelectorAll('.plotly-graph-div').forEach((div, i) => {
    const texts = Array.from(div.querySelectorAll('text')).filter(t => t.textContent.trim() && box(t).width > 0
        && !t.closest('.hoverlayer') && !t.closest('.modebar'));
    const own = t => t.closest('g.legend') || t.closest('g.colorbar');
    const free = texts.filter(t => !own(t));
    for (let a = 0; a < free.length; a++)
      for (let b = a + 1; b < free.length; b++)
        if (hit(box(free[a]), box(free[b]))) found.push([i, free[a].textContent, free[b].textContent]);
    div.querySelectorAll('g.legend rect.bg, g.colorbar, .modebar').forEach(g => {
      free.forEach(t => { if (hit(box(g), box(t))) found.push([i, g.getAttribute('class'), t.textContent]); });
    });
    const legends = Array.from(div.querySelectorAll('g.legend rect.bg')), bars = Array.from(div.querySelectorAll('g.colorbar'));
    legends.forEach(l => bars.forEach(c => { if (hit(box(l), box(c))) found.push([i, 'legend', 'colour bar']); }));
  });
  return found;
})()
"""


def _shoot_plots(dt, session, name: str) -> list[Path]:
    """Each plot of the page as a PNG (artefacts for people to look at)."""
    count = dt.send("Runtime.evaluate", {"expression": "document.querySelectorAll('.plotly-graph-div').length",
                                         "returnByValue": True}, session=session)["result"]["value"]
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    paths = []
    for k in range(count):
        x, y, w, h = dt.send("Runtime.evaluate", {"expression": f"(d => {{d.scrollIntoView(); const r = "
                             f"d.getBoundingClientRect(); return [r.left + scrollX, r.top + scrollY, r.width, "
                             f"Math.min(r.height, innerHeight)];}})(document.querySelectorAll('.plotly-graph-div')[{k}])",
                             "returnByValue": True}, session=session)["result"]["value"]
        shot = dt.send("Page.captureScreenshot", {"format": "png",
                                                  "clip": {"x": x, "y": y, "width": w, "height": h, "scale": 1}},
                       session=session)
        path = ARTIFACTS / f"{name}-plot{k}.png"
        path.write_bytes(base64.b64decode(shot["data"]))
        paths.append(path)
    return paths


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed")
@pytest.mark.parametrize("width", [1400, 1000])
def test_no_text_overprints_in_the_report_and_robust_charts(report_file, tmp_path, width):
    """The report (Pareto front, traces, piezohydraulic against DC, force path)
    and robust.html (front with its colour bar, sensitivity), drawn in a window
    of ``width`` px: no two texts overlap, nor the legend and the colour bar."""
    from ..conftest import FAST_REQUIREMENTS, run_cli
    req = tmp_path / "req.toml"
    req.write_text(FAST_REQUIREMENTS.replace("max_stacks = 2", "max_stacks = 12").replace("max_simulated = 2", "max_simulated = 4"))
    code, _, err = run_cli("robust", req, "--samples", "4", "--designs", "3", "--workers", "0", "--out",
                           tmp_path / "robust", "--quiet")
    assert code == 0, err
    dt = DevTools(tmp_path / "profile")
    try:
        for name, page in (("solve", report_file), ("robust", tmp_path / "robust" / "robust.html")):
            target = dt.send("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = dt.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            for domain in ("Page", "Runtime"):
                dt.send(f"{domain}.enable", session=session)
            dt.send("Emulation.setDeviceMetricsOverride", {"width": width, "height": 900, "deviceScaleFactor": 1,
                                                           "mobile": False}, session=session)
            dt.send("Page.navigate", {"url": page.as_uri()}, session=session)
            deadline = time.monotonic() + 30
            while not any(e.get("method") == "Page.loadEventFired" and e.get("sessionId") == session for e in dt.events):
                dt.events.append(dt._read(deadline))
            found = None
            for _ in range(50):           # plotly draws right after load
                drawn = dt.send("Runtime.evaluate", {"expression": "(d => d.length > 0 && d.every(x => x.querySelector("
                                "'svg.main-svg')))(Array.from(document.querySelectorAll('.plotly-graph-div')))",
                                "returnByValue": True}, session=session)["result"]["value"]
                if drawn:
                    time.sleep(0.3)
                    found = dt.send("Runtime.evaluate", {"expression": OVERPRINT_JS, "returnByValue": True},
                                    session=session)["result"]["value"]
                    break
                time.sleep(0.1)
            shots = _shoot_plots(dt, session, f"{name}-{width}px")
            assert found == [], (name, width, found[:8])
            assert shots and all(p.stat().st_size > 2_000 for p in shots)
    finally:
        dt.close()
