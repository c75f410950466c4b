#!/usr/bin/env python3
"""The HTML report in a real browser: runs `dcel diff --keep-going --html` on a
program with two planted bugs, loads the page in headless Chromium and checks
the DOM after its script ran, then takes a screenshot for a person to look at.

    html_browser_test.py DCEL_CLI IMPL OUT_DIR [SHARDS]

With SHARDS, the page is the one `dcel diff-merge --html` writes for SHARDS
runs of --shard K/SHARDS, and the same checks apply.

The command carries a hostile environment assignment, so the page shows
markup that must stay text. Checks: the verdict and a summary entry per
failure of the JSON report; one section per failure, each with its picture;
the script ran (the page's CSP allows it by its hash, and nothing else); every
vertex of every picture has a tooltip with its id and its exact coordinates;
the page's #selftest (which hovers the first vertex and pins the first
difference) shows the tooltip and draws the difference; the hostile text is
text, no element; nothing in the page points outside it (and its CSP would
refuse it: default-src 'none'). The screenshot goes to
OUT_DIR/report.png. Exit 77 (ctest: skipped) when Chromium is not installed.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from html.parser import HTMLParser

# No name resolves: the page needs no network, and the browser's own
# background requests (updates, accounts) go nowhere.
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--disable-extensions", "--hide-scrollbars",
         "--host-resolver-rules=MAP * ~NOTFOUND"]
HOSTILE = "</script><img src=x onerror=alert(1)>"


def chromium():
    for name in (os.environ.get("DCEL_CHROMIUM"), "chromium", "chromium-browser"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def browse(browser, args, url):
    """Runs headless Chromium on the page with a fresh profile; its stdout."""
    with tempfile.TemporaryDirectory(prefix="dcel-chromium-") as profile:
        r = subprocess.run([browser] + FLAGS + ["--user-data-dir=" + profile] + args + [url],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    if r.returncode != 0:
        fail("chromium failed (%d): %s" % (r.returncode, r.stderr.decode(errors="replace")[-2000:]))
    return r.stdout.decode()


class Dom(HTMLParser):
    """The elements of the dumped DOM, each [tag, attributes, text inside], in order."""

    VOID = ("meta", "link", "br", "img", "input", "hr")

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.elements = []
        self.open = []

    def handle_starttag(self, tag, attrs):
        e = [tag, dict(attrs), ""]
        self.elements.append(e)
        if tag not in self.VOID:
            self.open.append(e)

    def handle_startendtag(self, tag, attrs):
        self.elements.append([tag, dict(attrs), ""])

    def handle_endtag(self, tag):
        while self.open:
            if self.open.pop()[0] == tag:
                break

    def handle_data(self, data):
        for e in self.open:
            e[2] += data


def classes(e):
    return e[1].get("class", "").split()


def fail(message):
    sys.exit("html browser test: " + message)


def main():
    cli, impl, out = sys.argv[1], sys.argv[2], os.path.abspath(sys.argv[3])
    shards = int(sys.argv[4]) if len(sys.argv) > 4 else 0
    browser = chromium()
    if browser is None:
        print("skipped: Chromium not found (Debian's chromium: scripts/install-deps browser; or set DCEL_CHROMIUM)")
        return 77
    os.makedirs(out, exist_ok=True)
    page, report = os.path.join(out, "report.html"), os.path.join(out, "report.json")
    impl = "HOSTILE='%s' %s" % (HOSTILE, impl)
    start = time.monotonic()
    run = [cli, "diff", "--impl", impl, "--stream", "--keep-going", "--cases", "40"]
    if shards:
        parts = [os.path.join(out, "shard-%d.json" % k) for k in range(1, shards + 1)]
        for k, part in enumerate(parts, 1):
            subprocess.run(run + ["--shard", "%d/%d" % (k, shards), "--report", part],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=600)
        r = subprocess.run([cli, "diff-merge"] + parts + ["--html", page, "--report", report],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
    else:
        r = subprocess.run(run + ["--html", page, "--report", report],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, timeout=600)
    if r.returncode != 1:
        fail("dcel diff exited with %d, expected 1 (failures): %s" % (r.returncode, r.stdout.decode()[-2000:]))
    ran = time.monotonic() - start
    with open(report) as f:
        failures = json.load(f)["failures"]
    if len(failures) != 2:
        fail("expected two distinct failures, the report has %d" % len(failures))

    url = "file://" + page + "#selftest"
    start = time.monotonic()
    dom = browse(browser, ["--dump-dom"], url)
    parser = Dom()
    parser.feed(dom)
    elements = parser.elements

    # The script ran: the CSP allowed it by its hash.
    body = next(e for e in elements if e[0] == "body")
    if body[1].get("data-selftest") != "done":
        fail("the page's script did not run (is its CSP hash right?)")
    csp = [e[1].get("content", "") for e in elements
           if e[0] == "meta" and e[1].get("http-equiv", "").lower() == "content-security-policy"]
    if not csp or "default-src 'none'" not in csp[0]:
        fail("no Content-Security-Policy with default-src 'none'")

    # The summary: the verdict, and a link to each failure.
    h1 = next((e for e in elements if e[0] == "h1"), None)
    if h1 is None or not h1[2].startswith("dcel diff: 2 distinct failures in 40 cases"):
        fail("the verdict is %r" % (h1,))
    summary = next((e for e in elements if e[1].get("id") == "summary"), None)
    links = [e[1].get("href") for e in elements if e[0] == "a" and e[1].get("href", "").startswith("#failure-")]
    if summary is None or links != ["#failure-%d" % f["id"] for f in failures]:
        fail("the summary links %s" % links)

    # One section per failure, each with its picture.
    sections = [e for e in elements if e[0] == "section" and "failure" in classes(e)]
    if [s[1].get("id") for s in sections] != ["failure-%d" % f["id"] for f in failures]:
        fail("failure sections %s for %d failures" % ([s[1].get("id") for s in sections], len(failures)))
    svgs = [e for e in elements if e[0] == "svg"]
    if len(svgs) != len(failures):
        fail("%d pictures for %d failures" % (len(svgs), len(failures)))

    # Every vertex of every picture, in both panels: its id and coordinates, exactly the report's.
    hits = [e for e in elements if e[0] == "circle" and "hit" in classes(e)]
    expected = []
    for f in failures:
        tips = [(v, x, y) for v, (x, y) in enumerate(f["counterexample"]["graph"]["vertices"])]
        expected += tips + tips  # the reference's panel and the answer's

    def read_tip(text):
        m = re.fullmatch(r"v(\d+) \((\S+), (\S+)\)(, isolated)?", text)
        return (int(m.group(1)), float(m.group(2)), float(m.group(3))) if m else None
    got = [read_tip(e[1].get("aria-label", "")) for e in hits]
    if got != expected:
        fail("vertex tooltips %s, expected %s" % (got[:8], expected[:8]))

    # #selftest hovered a vertex: the tooltip shows it; and pinned a difference: its walk is drawn.
    tip = next((e for e in elements if e[1].get("id") == "tip"), None)
    if tip is None or "hidden" in tip[1] or read_tip(tip[2]) not in expected:
        fail("the hovered vertex shows no tooltip: %r" % (tip,))
    pinned = [e for e in elements if "walk" in classes(e) and "pinned" in classes(e)]
    drawn = [e for e in elements if e[0] == "path" and "hl" in classes(e)]
    if len(pinned) != 1 or not drawn:
        fail("the pinned difference is not drawn (%d pinned, %d strokes)" % (len(pinned), len(drawn)))

    # The hostile command is text: no image, and shown as typed.
    if any(e[0] == "img" for e in elements):
        fail("an <img> element: the command's text became markup")
    if not any(e[0] == "code" and HOSTILE in e[2] for e in elements):
        fail("the command's text %r is not shown" % HOSTILE)

    # Nothing points outside the page.
    for e in elements:
        for name in ("src", "href", "xlink:href", "action", "data"):
            value = e[1].get(name)
            if value is not None and not value.startswith("#"):
                fail("<%s %s=%r>: the page must refer to nothing outside itself" % (e[0], name, value))
    loaded = time.monotonic() - start

    shot = os.path.join(out, "report.png")
    start = time.monotonic()
    browse(browser, ["--screenshot=" + shot, "--window-size=1400,1800"], url)
    if not os.path.exists(shot) or os.path.getsize(shot) < 10000:
        fail("no screenshot in " + shot)
    print("html report: %d failure sections, %d pictures, %d vertex tooltips with exact coordinates, tooltip %r, "
          "a pinned difference drawn with %d strokes, the hostile command as text, nothing outside the page; dcel diff %.1f s, DOM %.1f s, screenshot %.1f s in %s"
          % (len(sections), len(svgs), len(hits), tip[2], len(drawn), ran, loaded,
             time.monotonic() - start, shot))
    return 0


if __name__ == "__main__":
    sys.exit(main())
