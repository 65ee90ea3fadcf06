#!/usr/bin/env python3
"""The HTML report (DIR/index.html of `fdhcert report`) opened in Debian's headless Chromium.

Makes a quick report in a folder of its own, then has Chromium (no sandbox, which root needs;
a profile folder of the test's own) take a screenshot and dump the page's DOM after its script
ran. Fails when the page logged anything to the console (an error of its script or a resource it
could not load), when the DOM lacks the charts (one inline <svg> per chart, a hoverable circle
with a <title> per speed-against-accuracy row) or the links to the counterexamples, or when the
screenshot is blank. Exit 77 (skipped) without chromium.

usage: check_report_page.py FDHCERT SOURCE_DIR [--screenshot FILE] [--report DIR] [--height PX]
  --screenshot FILE  also keep the screenshot there (docs/report/screenshot.png)
  --report DIR       check DIR/index.html as it is instead of making a quick report
  --height PX        the window's height (default 3000; the committed screenshot: 4400, down to
                     the speed-against-accuracy chart)
"""
import argparse
import csv
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

WIDTH = 1280


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def png_pixels(path):
    """(width, height, bytes per pixel, rows of unfiltered bytes) of an 8-bit, non-interlaced
    RGB or RGBA PNG, as Chromium writes them (PNG specification, sections 7 and 9)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + ": not a PNG")
    at, idat, head = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            head = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = head
    if depth != 8 or colour not in (2, 6) or interlace:
        fail(f"{path}: a PNG of depth {depth}, colour type {colour}: not read here")
    bpp = 3 if colour == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
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
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def check_screenshot(path):
    width, height, bpp, rows = png_pixels(path)
    colours, inked = set(), 0
    for row in rows[::4]:
        for x in range(0, width * bpp, bpp * 4):
            pixel = row[x:x + 3]
            colours.add(pixel)
            inked += pixel != b"\xff\xff\xff"
    if len(colours) < 8 or inked < 1000:
        fail(f"{path}: the screenshot looks blank ({len(colours)} colours, {inked} inked samples)")
    return len(colours)


def chromium(args, profile, height):
    run = subprocess.run(
        ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0",
         f"--window-size={WIDTH},{height}"] + args,
        capture_output=True, text=True, timeout=300)
    console = [line for line in run.stderr.splitlines() if ":CONSOLE" in line]
    if console:
        fail("the page wrote to the console:\n" + "\n".join(console))
    if run.returncode != 0:
        fail(f"chromium ended with status {run.returncode}:\n{run.stderr[-2000:]}")
    return run.stdout


def check_dom(dom, report):
    speed = list(csv.DictReader(open(os.path.join(report, "data", "speed_accuracy.csv"))))
    charts = len(re.findall(r"<svg[ >]", dom))
    kinds = len({row["kind"] for row in speed})
    images = len(re.findall(r"!\[[^]]*\]\([^)]*\.svg\)", open(os.path.join(report, "report.md")).read()))
    if charts < images - 1 + kinds:
        fail(f"{charts} inline <svg> in the page, for {images} charts of report.md")
    points = re.findall(r'<circle class="point"[^>]*data-method="([^"]+)"[^>]*>\s*<title>([^<]+)</title>', dom)
    if len(points) != len(speed):
        fail(f"{len(points)} hoverable points for {len(speed)} rows of data/speed_accuracy.csv")
    for method, title in points:
        if not re.search(r"^\S+ on \S+ \(\w+\): FP rate \S+, FN rate \S+ of \d+ queries; [0-9.]+ ns per query$", title):
            fail("a point's title does not name its method, family, FP, FN and ns: " + title)
    for case in re.findall(r'<a href="(peers/[^"]+)"', dom):
        if not os.path.isfile(os.path.join(report, case)):
            fail("a counterexample's link leads nowhere: " + case)
    if "peers/" in open(os.path.join(report, "certificate.md")).read() and '<a href="peers/' not in dom:
        fail("the certificate's counterexamples are not linked")
    if re.search(r'(src|href)="(https?:)?//', dom):
        fail("the page loads something from the network")
    return charts, len(points)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("fdhcert")
    parser.add_argument("source")
    parser.add_argument("--screenshot")
    parser.add_argument("--report")
    parser.add_argument("--height", type=int, default=3000)
    o = parser.parse_args()
    if not shutil.which("chromium"):
        print("skipped: no chromium (Debian package chromium; ./run installs it as root)")
        return 77
    work = tempfile.mkdtemp(prefix="fdh_report_page.")
    try:
        report = o.report or os.path.join(work, "report")
        if not o.report:
            subprocess.run([o.fdhcert, "report", "--quick", "--quiet", "--summary", "--out", report],
                           cwd=o.source, check=True, stdout=subprocess.DEVNULL)
        page = "file://" + os.path.abspath(os.path.join(report, "index.html"))
        shot = os.path.join(work, "screenshot.png")
        chromium(["--screenshot=" + shot, page], os.path.join(work, "profile-shot"), o.height)
        colours = check_screenshot(shot)
        charts, points = check_dom(chromium(["--dump-dom", page], os.path.join(work, "profile-dom"), o.height), report)
        if o.screenshot:
            shutil.copyfile(shot, o.screenshot + ".tmp")
            os.replace(o.screenshot + ".tmp", o.screenshot)
        print(f"ok: {charts} inline charts, {points} hoverable points, screenshot of {colours} colours")
        return 0
    finally:
        if os.environ.get("FDH_KEEP_TEST_FILES") == "1":
            print("kept: " + work)
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
