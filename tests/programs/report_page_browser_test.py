#!/usr/bin/env python3
"""The report page in a real browser (docs/report.md, "The page"): headless Chromium from Debian,
driven through chromedriver's W3C WebDriver HTTP API with the standard library only.

Writes a small real report (iblkit-report: the lone mirror and diffuse spheres under sky, 96x54),
loads report.html from file://, and checks that
  - the page loads with no console errors (goog:loggingPrefs browser log, level SEVERE);
  - the mirror sphere is not scored in the diffuse-only sh mode (marked n/a in the summary);
  - a key press (ArrowRight) flips the large view to the next image (its img src);
  - the page's JavaScript tone curve, applied to the case's linear RGBE data at the case's
    exposure, gives the report's own PNG (written by core's toneMap) within 1/255 per channel;
  - the exposure control (the ']' key) draws the canvas, and 'h' shows the heat map;
and writes screenshots under ARTIFACTS (report-page.png, report-page-viewer.png).
Exits 77 (ctest: skipped) with a message when chromium or chromedriver is absent.

usage: report_page_browser_test.py BIN_DIR ASSETS_DIR ARTIFACTS_DIR
"""
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import time
import urllib.request
import zlib


def fail(message):
    print("report_page_browser_test: FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def read_png(data):
    """RGB(A) 8-bit PNG bytes -> (width, height, channels, rows of bytes)."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                fail("PNG is not 8-bit RGB or RGBA")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


class Driver:
    def __init__(self, port):
        self.base = "http://127.0.0.1:%d" % port

    def call(self, method, path, body=None):
        request = urllib.request.Request(self.base + path, method=method,
                                         data=None if body is None else json.dumps(body).encode(),
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=60) as response:
                return json.loads(response.read() or b"{}").get("value")
        except urllib.error.HTTPError as error:
            fail("%s %s: %s" % (method, path, error.read().decode(errors="replace")[:400]))

    def script(self, source, *args):
        return self.call("POST", "/session/%s/execute/sync" % self.session, {"script": source, "args": list(args)})

    def async_script(self, source, *args):
        return self.call("POST", "/session/%s/execute/async" % self.session, {"script": source, "args": list(args)})

    def browser_log(self):
        return self.call("POST", "/session/%s/se/log" % self.session, {"type": "browser"}) or []

    def press(self, key):
        self.call("POST", "/session/%s/actions" % self.session, {"actions": [{"type": "key", "id": "keyboard", "actions": [
            {"type": "keyDown", "value": key}, {"type": "keyUp", "value": key}]}]})
        self.call("DELETE", "/session/%s/actions" % self.session)


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    bin_dir, assets, artifacts = sys.argv[1:4]
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    chromedriver = shutil.which("chromedriver")
    if not chromium or not chromedriver:
        print("report_page_browser_test: SKIPPED: chromium or chromedriver not installed "
              "(scripts/setup.sh installs Debian's chromium and chromium-driver)")
        sys.exit(77)
    os.makedirs(artifacts, exist_ok=True)
    out = os.path.join(artifacts, "report")
    report = subprocess.run(
        [os.path.join(bin_dir, "iblkit-report"), os.path.join(assets, "scenes/mirror_sphere.json"),
         os.path.join(assets, "scenes/diffuse_sphere.json"), "--envs", "sky", "--env-dir", os.path.join(assets, "hdri"),
         "--modes", "mirror,sh,full", "--width", "96", "--height", "54", "--min-passes", "2", "--max-passes", "2",
         "--bench", "2", "--cache", os.path.join(artifacts, "cache"), "-o", out, "--force"],
        capture_output=True, text=True)
    if report.returncode != 0:
        fail("iblkit-report: " + report.stderr.strip()[-600:])

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    server = subprocess.Popen([chromedriver, "--port=%d" % port], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        driver = Driver(port)
        for _ in range(100):
            try:
                if driver.call("GET", "/status").get("ready"):
                    break
            except Exception:
                pass
            time.sleep(0.1)
        session = driver.call("POST", "/session", {"capabilities": {"alwaysMatch": {
            "browserName": "chrome",
            "goog:chromeOptions": {"binary": chromium, "args": [
                "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1400,1000"]},
            "goog:loggingPrefs": {"browser": "ALL"}}}})
        driver.session = session["sessionId"]
        try:
            check_page(driver, out, artifacts)
        finally:
            driver.call("DELETE", "/session/" + driver.session)
    finally:
        server.terminate()
        server.wait(timeout=10)
    print("report_page_browser_test: passed; screenshots in " + artifacts)


def expect_no_console_errors(driver, when):
    errors = [entry for entry in driver.browser_log() if entry.get("level") == "SEVERE"]
    if errors:
        fail("console errors %s: %s" % (when, "; ".join(entry.get("message", "") for entry in errors)))


def check_page(driver, out, artifacts):
    page = "file://" + os.path.abspath(os.path.join(out, "report.html"))
    driver.call("POST", "/session/%s/url" % driver.session, {"url": page})
    expect_no_console_errors(driver, "on load")
    with open(os.path.join(artifacts, "report-page.png"), "wb") as file:
        file.write(base64.b64decode(driver.call("GET", "/session/%s/screenshot" % driver.session)))

    # The summary marks sh n/a on the mirror sphere (no diffuse lobe), and no case of it scored sh.
    if not driver.script("return Array.from(document.querySelectorAll('td.na')).some("
                         "td => td.title.includes('no diffuse lobe'));"):
        fail("the summary does not mark a diffuse-only mode n/a on the mirror sphere")
    report = json.load(open(os.path.join(out, "report.json")))
    mirror = [c for c in report["cases"] if c["scene"] == "mirror_sphere"][0]
    if [m["mode"] for m in mirror["modes"]] != ["mirror", "full"]:
        fail("mirror_sphere scored %s, not mirror and full" % [m["mode"] for m in mirror["modes"]])

    # Open the first case, make its view the active one, press a key.
    state = driver.script("""
        const details = document.querySelector('details.case'); details.open = true;
        const viewer = details.querySelector('.viewer'); viewer.focus(); viewer.scrollIntoView();
        const buttons = Array.from(viewer.querySelectorAll('.items button'));
        return {case: viewer.dataset.case, linear: viewer.dataset.linear, exposure: parseFloat(viewer.dataset.exposure),
                src: viewer.querySelector('img.large').getAttribute('src'), sources: buttons.map(b => b.dataset.src)};""")
    if state["src"] != state["sources"][0]:
        fail("the large view starts at %s, not %s" % (state["src"], state["sources"][0]))
    driver.press("\ue014")  # ArrowRight
    shown = driver.script("return document.querySelector('details.case .viewer img.large').getAttribute('src');")
    if shown != state["sources"][1]:
        fail("after ArrowRight the large view shows %s, not the next image %s" % (shown, state["sources"][1]))
    driver.press("h")
    shown = driver.script("return document.querySelector('details.case .viewer img.large').getAttribute('src');")
    if not shown.endswith("-flip.png"):
        fail("after h the large view shows %s, not the heat map" % shown)
    driver.press("h")

    # The page's tone curve on the linear data against the report's PNG of the reference.
    url = driver.async_script("const done = arguments[arguments.length - 1];"
                              "iblkitToneMapped(arguments[0], arguments[1], 'reference', arguments[2])"
                              ".then(done, e => done('error: ' + e.message));",
                              state["case"], state["linear"], state["exposure"])
    if not url.startswith("data:image/png;base64,"):
        fail("the page could not tone-map the linear reference: " + url)
    w1, h1, c1, page_rows = read_png(base64.b64decode(url.split(",", 1)[1]))
    w2, h2, c2, png_rows = read_png(open(os.path.join(out, state["sources"][0]), "rb").read())
    if (w1, h1) != (w2, h2):
        fail("tone-mapped size %dx%d, PNG %dx%d" % (w1, h1, w2, h2))
    worst = max(abs(page_rows[y][x * c1 + c] - png_rows[y][x * c2 + c])
                for y in range(h1) for x in range(w1) for c in range(3))
    print("largest difference between the page's tone mapping and the PNG: %d/255" % worst)
    if worst > 1:
        fail("the page's tone curve differs from core's by %d/255" % worst)

    driver.press("]")
    driver.press("]")
    for _ in range(50):
        if driver.script("return document.querySelector('details.case .viewer').dataset.drawn;") == "canvas":
            break
        time.sleep(0.1)
    else:
        fail("the exposure control did not draw the canvas")
    viewer = driver.call("POST", "/session/%s/element" % driver.session,
                         {"using": "css selector", "value": "details.case .viewer"})
    element = list(viewer.values())[0]
    with open(os.path.join(artifacts, "report-page-viewer.png"), "wb") as file:
        file.write(base64.b64decode(driver.call("GET", "/session/%s/element/%s/screenshot" % (driver.session, element))))
    expect_no_console_errors(driver, "after the key presses")


if __name__ == "__main__":
    main()
