"""Helpers of the browser tests (tests/view/): headless Chromium driven directly (not through the
code under test) by Selenium's ChromeDriver, a PNG decoder (zlib + the five PNG row filters,
RFC 2083), pixel counts.

One browser serves every screenshot of a test process (started at the first, closed at exit):
launching Chromium once per picture cost 7-13 s each on the loaded 2-core machine, a page in the
running browser about 2 s. Chromium's flags are the ones that work here as root with no GPU:
WebGL through SwiftShader."""
import atexit
import os
import shutil
import struct
import zlib
from collections import Counter
from pathlib import Path

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
         "--use-angle=swiftshader", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
         "--force-device-scale-factor=1"]


def chromium():
    """The Chromium binary, or None when it is not installed."""
    chosen = os.environ.get("IMPLICITFIT_CHROMIUM")
    if chosen:
        return chosen if os.access(chosen, os.X_OK) else None
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        path = shutil.which(name)
        if path:
            return path
    return None


def missing():
    """Why the browser tests cannot run here (None when they can)."""
    if chromium() is None:
        return "Chromium is not installed (apt-get install chromium)"
    if shutil.which("chromedriver") is None:
        return "ChromeDriver is not installed (apt-get install chromium-driver)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "Selenium is not installed (apt-get install python3-selenium)"
    return None


_driver = None


def _browser():
    global _driver
    if _driver is None:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        options = webdriver.ChromeOptions()
        options.binary_location = chromium()
        for flag in FLAGS:
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})  # the page's console
        _driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")),
                                   options=options)
        _driver.set_page_load_timeout(120)
        atexit.register(_driver.quit)
    return _driver


def screenshot(page, png, width=400, height=300, fragment=""):
    """Draws the page (a file) into png at width x height CSS pixels; returns the PNG path.
    Fails when the page's script throws (an uncaught error in the console)."""
    driver = _browser()
    url = Path(page).resolve().as_uri() + ("#" + fragment if fragment else "")
    driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride",
                           {"width": width, "height": height, "deviceScaleFactor": 1,
                            "mobile": False})
    driver.get("about:blank")  # a new fragment alone would not reload the page
    driver.get(url)  # returns after the load event: the viewer draws synchronously on load
    Path(png).write_bytes(driver.get_screenshot_as_png())
    errors = [e["message"] for e in driver.get_log("browser")
              if e["level"] == "SEVERE" and "Uncaught" in e["message"]]
    assert not errors, f"{page}#{fragment}: {errors}"
    return png


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def read_png(path):
    """(width, height, rows): rows[y] is a bytes object of width RGB triples (8-bit RGB or RGBA
    PNGs, not interlaced: what Chromium writes)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, f"{path}: unsupported PNG {header}"
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif kind == 2:
            for i in range(stride):
                line[i] = (line[i] + previous[i]) & 255
        elif kind == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                up_left = previous[i - channels] if i >= channels else 0
                line[i] = (line[i] + _paeth(left, previous[i], up_left)) & 255
        else:
            assert kind == 0, f"{path}: unknown PNG filter {kind}"
        previous = line
        if channels == 4:
            rgb = bytearray(width * 3)
            rgb[0::3], rgb[1::3], rgb[2::3] = line[0::4], line[1::4], line[2::4]
            rows.append(bytes(rgb))
        else:
            rows.append(bytes(line))
    return width, height, rows


def colour_counts(rows):
    """Counter of (r, g, b) over every pixel."""
    counts = Counter()
    for row in rows:
        counts.update(zip(row[0::3], row[1::3], row[2::3]))
    return counts


def background(rows):
    """The colour of the top-left pixel (the tests hide the panel)."""
    return tuple(rows[0][0:3])
