#!/usr/bin/env python3
"""The HTML report as a reader opens it: a small report of seed, opened in headless Chromium.
No console errors; every chart laid out with size and with one point per configuration, all
inside it; every picture decoded; the table one row per configuration with DSSIM its last
column; nothing wider than the window. It prints to a PDF of its own pages, and its screenshot
shows the charts' front colour. Usage: report-browser-test.py BINARY [KEEP_DIR] (KEEP_DIR keeps
the report, the PDF and the screenshot)."""
import html
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib

WINDOW = (1280, 2000)
FRONT_COLOUR = (0xE8, 0x71, 0x0A)   # the first light's front and points (ReportWriter's kLightColours)
SWEEP = [
    {"label": "defaults", "set": {}},
    {"label": "hard", "set": {"filter.mode": "hard"}},
    {"label": "pcf 5", "set": {"filter.mode": "pcf", "filter.kernel": 5}},
    {"label": "acne", "set": {"bias.cull_front": False, "bias.footprint": False, "bias.skip_floors": False, "bias.slope": 0, "bias.min": 0, "filter.mode": "hard"}},
]

# Runs before anything of the page: records script errors, console.error and pictures that fail
# to load; once the page has loaded, measures what a reader would see and writes it into the page
# as JSON for --dump-dom to carry out.
CHECK = """<script>
(() => {
  const problems = [];
  window.addEventListener('error', e => problems.push(e.message || ('failed to load ' + (e.target.src || e.target.tagName))), true);
  const consoleError = console.error;
  console.error = (...args) => { problems.push('console.error: ' + args.join(' ')); consoleError(...args); };
  window.addEventListener('load', () => {
    const charts = [...document.querySelectorAll('svg.chart')].map(svg => {
      const box = svg.getBoundingClientRect();
      const points = [...svg.querySelectorAll('circle')];
      const outside = points.filter(c => {
        const p = c.getBoundingClientRect();
        return p.width === 0 || p.left < box.left || p.right > box.right || p.top < box.top || p.bottom > box.bottom;
      }).length;
      return {width: box.width, height: box.height, points: points.length, outside: outside,
              fronts: svg.querySelectorAll('circle.onfront').length, labels: svg.querySelectorAll('text.label').length};
    });
    const images = [...document.images];
    const table = [...document.querySelectorAll('table')][0];
    const result = {
      problems: problems,
      charts: charts,
      images: images.length,
      brokenImages: images.filter(i => !i.complete || i.naturalWidth === 0).length,
      tableRows: table ? table.querySelectorAll('tr').length - 1 : 0,
      lastColumn: table ? table.querySelector('tr').lastElementChild.textContent : '',
      overflow: document.documentElement.scrollWidth - window.innerWidth,
    };
    const out = document.createElement('pre');
    out.id = 'shadowlab-check';
    out.textContent = JSON.stringify(result);
    document.body.appendChild(out);
  });
})();
</script>"""


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def chromium(work, *arguments):
    """Chromium headless on `arguments`; its stdout, after failing on any console message."""
    command = ["chromium", "--headless=new", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr", "--v=0",
               "--user-data-dir=" + os.path.join(work, "chromium-profile"), "--window-size=%d,%d" % WINDOW, *arguments]
    run = subprocess.run(command, capture_output=True, text=True, timeout=180, cwd=work)
    if run.returncode != 0:
        fail("chromium exited with %d:\n%s" % (run.returncode, run.stderr[-3000:]))
    console = [line for line in run.stderr.splitlines() if ":CONSOLE" in line or "Uncaught" in line]
    if console:
        fail("the page wrote to the console:\n" + "\n".join(console))
    return run.stdout


def write_report(binary, work):
    sweep = os.path.join(work, "sweep.json")
    with open(sweep, "w") as f:
        json.dump(SWEEP, f)
    out = os.path.join(work, "report")
    # The quickest report `shadowlab help report` offers: one frame each, no warm-up, one area
    # ray a pixel, no flicker walk.
    run = subprocess.run([binary, "report", "--scene", "seed", "--size", "160x90", "--sweep", sweep, "--frames", "1", "--warmup", "0",
                          "--area-samples", "1", "--flicker-frames", "0", "--out", out],
                         capture_output=True, text=True, timeout=300, env={**os.environ, "QT_QPA_PLATFORM": "headless"})
    if run.returncode != 0:
        fail("report exited with %d:\n%s" % (run.returncode, run.stderr))
    return os.path.join(out, "report.html")


def check_layout(work, page):
    with open(page, encoding="utf-8") as f:
        text = f.read()
    checked = os.path.join(work, "checked.html")
    with open(checked, "w", encoding="utf-8") as f:
        f.write(text.replace("<head>", "<head>" + CHECK, 1))
    dom = chromium(work, "--dump-dom", "file://" + checked)
    found = re.search(r'<pre id="shadowlab-check">(.*?)</pre>', dom, re.S)
    if not found:
        fail("the page's check did not run (no result in the DOM dump)")
    result = json.loads(html.unescape(found.group(1)))
    print("layout:", json.dumps(result))
    if result["problems"]:
        fail("errors while the page loaded: %s" % result["problems"])
    if len(result["charts"]) != 2:
        fail("%d charts, not the two (misclassified, area MAE)" % len(result["charts"]))
    for i, chart in enumerate(result["charts"]):
        if chart["width"] < 400 or chart["height"] < 200:
            fail("chart %d is laid out %gx%g px" % (i + 1, chart["width"], chart["height"]))
        if chart["points"] != len(SWEEP) or chart["outside"] != 0:
            fail("chart %d has %d points (%d outside it) for %d configurations" % (i + 1, chart["points"], chart["outside"], len(SWEEP)))
        if chart["fronts"] < 1 or chart["labels"] < 1:
            fail("chart %d marks %d points on the front and labels %d" % (i + 1, chart["fronts"], chart["labels"]))
    if result["images"] < 4 or result["brokenImages"] != 0:
        fail("%d of %d error images do not show" % (result["brokenImages"], result["images"]))
    if result["tableRows"] != len(SWEEP) or result["lastColumn"] != "texels \u2264 1 px %":
        fail("the table has %d rows and ends with '%s'" % (result["tableRows"], result["lastColumn"]))
    if result["overflow"] > 0:
        fail("the page is %d px wider than a %d px window" % (result["overflow"], WINDOW[0]))


def check_pdf(work, page):
    pdf = os.path.join(work, "report.pdf")
    chromium(work, "--no-pdf-header-footer", "--print-to-pdf=" + pdf, "file://" + page)
    if not os.path.exists(pdf):
        fail("no PDF was printed")
    with open(pdf, "rb") as f:
        data = f.read()
    pages = len(re.findall(rb"/Type\s*/Page\b", data))
    print("pdf: %d bytes, %d pages" % (len(data), pages))
    if not data.startswith(b"%PDF-") or len(data) < 20000 or pages < 2:
        fail("the PDF is %d bytes of %d pages, starting %r" % (len(data), pages, data[:8]))


def png_pixels(path):
    """Width, height and rows of RGB(A) tuples of an 8-bit, non-interlaced PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("%s is not a PNG" % path)
    chunks, at = {}, 8
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        chunks.setdefault(kind, []).append(data[at + 8:at + 8 + length])
        at += 12 + length
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks[b"IHDR"][0])
    channels = {2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        fail("the screenshot is a PNG of a kind this test does not read (depth %d, colour %d)" % (depth, colour))
    raw = zlib.decompress(b"".join(chunks[b"IDAT"]))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            left = line[x - channels] if x >= channels else 0
            up, corner = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + left) & 0xFF
            elif kind == 2:
                line[x] = (line[x] + up) & 0xFF
            elif kind == 3:
                line[x] = (line[x] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - corner
                nearest = min((abs(p - left), 0, left), (abs(p - up), 1, up), (abs(p - corner), 2, corner))[2]
                line[x] = (line[x] + nearest) & 0xFF
        rows.append(line)
        previous = line
    return width, height, rows, channels


def check_screenshot(work, page):
    shot = os.path.join(work, "report.png")
    chromium(work, "--hide-scrollbars", "--screenshot=" + shot, "file://" + page)
    width, height, rows, channels = png_pixels(shot)
    front = sum(1 for line in rows for x in range(0, len(line), channels)
                if all(abs(line[x + c] - FRONT_COLOUR[c]) <= 24 for c in range(3)))
    print("screenshot: %dx%d, %d pixels of the front colour" % (width, height, front))
    if (width, height) != WINDOW:
        fail("the screenshot is %dx%d, not %dx%d" % (width, height, *WINDOW))
    if front < 200:
        fail("the screenshot shows %d pixels of the charts' front colour: the charts are not drawn" % front)


def main():
    if len(sys.argv) < 2:
        fail("usage: report-browser-test.py BINARY [KEEP_DIR]")
    binary = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as temporary:
        work = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else temporary
        os.makedirs(work, exist_ok=True)
        page = write_report(binary, work)
        check_layout(work, page)
        check_pdf(work, page)
        check_screenshot(work, page)
    print("the report opens, prints and shows its charts in Chromium")


if __name__ == "__main__":
    main()
