"""The web map at ``/`` in a real browser: Debian's chromium, headless, driven by selenium against a
``dggs serve`` process on 127.0.0.1 serving a store built here.

Run with ``make test-browser`` (or ``python -m pytest -q -m browser tests/server``). With
``DGGS_SCREENSHOT=docs/serve-globe.png`` set, the colour-classes test saves its screenshot of the globe
(coastlines, borders and cells coloured by a sum) there, for the docs.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import dggs
from dggs.storage import CellStore

pytestmark = pytest.mark.browser

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
WIDTH, HEIGHT = 1000, 640
TIMEOUT = 30.0
STORED_LEVEL = 9
# The server's cap on /map/cells features: the whole world at the stored level (about 5,500 cells) is
# over it, so the page must step to a coarser level; every view the tests set is under it.
MAX_FEATURES = 4500

# The data: two dense clusters (Europe, Africa: normal, cut to a box) and four small ones elsewhere;
# the oceans stay empty.
EUROPE = (47.5, 12.5)  # in lat 40..55, lng 0..25
AFRICA = (-7.5, 25.0)  # in lat -20..5, lng 15..35
ELSEWHERE = [(40.0, -100.0), (-15.0, -60.0), (35.0, 115.0), (-25.0, 135.0)]
EMPTY = [(20.0, -40.0), (-35.0, 75.0), (10.0, -20.0)]  # ocean, away from the data and the graticule
GLOBE_VIEW = {"center": [15.0, 20.0], "zoom": 1.7}
ARABIA = (23.0, 45.0)  # land with no data (away from the graticule)
LAND_COLOUR, SEA_COLOUR = (0x2C, 0x3A, 0x4A), (0x1B, 0x27, 0x36)  # app.js's LAND_COLOUR, GLOBE_COLOUR
EUROPE_VIEW = {"center": [EUROPE[1], EUROPE[0]], "zoom": 4.5}

webdriver = pytest.importorskip("selenium.webdriver")
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.webdriver.support.ui import Select, WebDriverWait  # noqa: E402

from .serving import free_port  # noqa: E402


# --- Fixtures ---------------------------------------------------------------------------------------
def _cluster(rng: np.random.Generator, n: int, centre: tuple[float, float], sd: tuple[float, float],
             box: tuple[float, float, float, float]) -> tuple[np.ndarray, np.ndarray]:
    """n points, normal around centre (lat, lng), inside box (s, n, w, e)."""
    lat, lng = np.empty(0), np.empty(0)
    while lat.size < n:
        a, b = rng.normal(centre[0], sd[0], n), rng.normal(centre[1], sd[1], n)
        keep = (a > box[0]) & (a < box[1]) & (b > box[2]) & (b < box[3])
        lat, lng = np.concatenate([lat, a[keep]]), np.concatenate([lng, b[keep]])
    return lat[:n], lng[:n]


def _points() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(12)
    europe = _cluster(rng, 6000, EUROPE, (4, 6), (40, 55, 0, 25))
    africa = _cluster(rng, 3000, AFRICA, (6, 5), (-20, 5, 15, 35))
    lat, lng = [europe[0], africa[0]], [europe[1], africa[1]]
    for clat, clng in ELSEWHERE:
        lat.append(rng.uniform(clat - 2, clat + 2, 50))
        lng.append(rng.uniform(clng - 2, clng + 2, 50))
    lat_a, lng_a = np.concatenate(lat), np.concatenate(lng)
    pop = rng.integers(1, 10_000, lat_a.size)
    return lat_a, lng_a, pop


@pytest.fixture(scope="module")
def data(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    lat, lng, pop = _points()
    path = tmp_path_factory.mktemp("browser-store") / "cells.db"
    with CellStore(path) as store:
        store.ingest_points(lat, lng, STORED_LEVEL, {"pop": pop})
    return {"path": path, "lat": lat, "lng": lng, "pop": pop}



def _serve_command(store: Path, port: int) -> list[str]:
    exe = Path(sys.executable).parent / "dggs"
    cli = [str(exe)] if exe.exists() else [sys.executable, "-c", "from dggs.cli import main; main()"]
    return [*cli, "serve", str(store), "--host", "127.0.0.1", "--port", str(port),
            "--max-features", str(MAX_FEATURES)]


def _get_json(url: str, timeout: float = 5.0) -> Any:
    opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # 127.0.0.1: never a proxy
    with opener.open(url, timeout=timeout) as response:
        return json.load(response)


@pytest.fixture(scope="module")
def server(data: dict[str, Any], tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    port = free_port()
    log = (tmp_path_factory.mktemp("serve-log") / "serve.log").open("w+")
    proc = subprocess.Popen(_serve_command(data["path"], port), stdout=log, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + TIMEOUT
        while True:
            if proc.poll() is not None:
                log.seek(0)
                pytest.fail(f"dggs serve exited with {proc.returncode}:\n{log.read()}")
            try:
                _get_json(f"{base}/map/layers", timeout=2.0)
                break
            except (OSError, urllib.error.URLError):
                if time.monotonic() > deadline:
                    log.seek(0)
                    pytest.fail(f"dggs serve did not answer in {TIMEOUT} s:\n{log.read()}")
                time.sleep(0.1)
        yield base
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:  # pragma: no cover
            proc.kill()
            proc.wait()
        log.close()


@pytest.fixture(scope="module")
def driver(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    if not (os.path.exists(CHROMIUM) and os.path.exists(CHROMEDRIVER)):  # pragma: no cover
        pytest.skip(
            f"the browser tests need Debian's chromium and chromium-driver ({CHROMIUM}, {CHROMEDRIVER}): "
            "apt-get install chromium chromium-driver, or make test-browser"
        )
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    profile = tmp_path_factory.mktemp("chromium-profile")
    for flag in (
        "--headless=new",
        "--no-sandbox",
        # WebGL without a GPU: ANGLE on SwiftShader (software Vulkan), allowed explicitly.
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--ignore-gpu-blocklist",
        # Nothing but 127.0.0.1.
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-default-apps",
        "--disable-extensions",
        "--disable-quic",
        "--no-proxy-server",
        "--no-first-run",
        "--no-default-browser-check",
        "--disable-dev-shm-usage",
        f"--window-size={WIDTH},{HEIGHT + 200}",
        f"--user-data-dir={profile}",
    ):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    browser = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    try:
        # A fixed viewport and pixel ratio, whatever the window decorations, so pixels are CSS pixels.
        browser.execute_cdp_cmd(
            "Emulation.setDeviceMetricsOverride",
            {"width": WIDTH, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False},
        )
        browser.set_script_timeout(TIMEOUT)
        yield browser
    finally:
        browser.quit()


@pytest.fixture(scope="module")
def page(driver: Any, server: str) -> Any:
    """The map page, loaded once, its first cells drawn; the tests set the view they need."""
    driver.get(f"{server}/")
    wait_for(driver, lambda: driver.execute_script("return document.body.dataset.state") in ("idle", "error"))
    wait_for(driver, lambda: driver.execute_script("return window.dggsState.geography") != "loading",
             message="the countries did not load")
    return driver


# --- Helpers ----------------------------------------------------------------------------------------
def wait_for(driver: Any, condition: Any, timeout: float = TIMEOUT, message: str = "") -> Any:
    return WebDriverWait(driver, timeout, poll_frequency=0.05).until(lambda _: condition(), message)


def state(driver: Any) -> dict[str, Any]:
    return driver.execute_script("return Object.assign({}, window.dggsState, {body: document.body.dataset.state})")


def settle(driver: Any, before: int, timeout: float = TIMEOUT) -> dict[str, Any]:
    """Wait until the page has rendered a fetch started after `before` renders and the map is idle."""

    def done() -> bool:
        s = state(driver)
        if s["body"] == "error":
            raise AssertionError(f"the page reports an error: {s['lastError']}")
        return s["body"] == "idle" and s["renders"] > before

    wait_for(driver, done, timeout, "the map did not become idle")
    return state(driver)


def set_view(driver: Any, view: dict[str, Any]) -> dict[str, Any]:
    before = state(driver)["renders"]
    driver.execute_script("window.dggsMap.jumpTo(Object.assign({bearing: 0, pitch: 0}, arguments[0]))", view)
    return settle(driver, before)


def choose(driver: Any, select_id: str, value: str) -> dict[str, Any]:
    before = state(driver)["renders"]
    Select(driver.find_element(By.ID, select_id)).select_by_value(value)
    return settle(driver, before)


def project(driver: Any, lat: float, lng: float) -> tuple[float, float]:
    """Page (CSS px) position of a location on the map."""
    x, y = driver.execute_script(
        "const p = window.dggsMap.project([arguments[1], arguments[0]]);"
        "const r = window.dggsMap.getCanvas().getBoundingClientRect();"
        "return [r.left + p.x, r.top + p.y];",
        lat,
        lng,
    )
    return float(x), float(y)


def js_errors(driver: Any) -> list[dict[str, Any]]:
    """The browser log's errors since the last call (reading empties the log). Chromium logs every HTTP
    error response; a 413 from /map/cells is the server asking for a coarser level, which the page does."""
    return [
        entry
        for entry in driver.get_log("browser")
        if entry["level"] == "SEVERE" and not (entry["source"] == "network" and "status of 413" in entry["message"])
    ]


class Screenshot:
    """A screenshot of the page (PNG from chromium), its pixels read back by drawing it on a 2D canvas in
    the page: no image library needed in Python."""

    def __init__(self, driver: Any) -> None:
        self.driver = driver
        self.png = driver.get_screenshot_as_base64()

    def region(self, x0: int, y0: int, width: int, height: int) -> np.ndarray:
        """The (height, width, 3) RGB pixels of a rectangle, in page px (the pixel ratio is 1)."""
        script = _DECODED_SCREENSHOT % """
          const [x, y, w, h] = points;
          done([img.width, img.height, Array.from(g.getImageData(x, y, w, h).data)]);"""
        result = self.driver.execute_async_script(script, self.png, [x0, y0, width, height])
        assert result is not None, "the screenshot did not decode"
        self.size = (result[0], result[1])
        return np.array(result[2], np.uint8).reshape(height, width, 4)[:, :, :3]

    def patch(self, x: float, y: float, radius: int = 2) -> np.ndarray:
        xi, yi = int(round(x)), int(round(y))
        return self.region(xi - radius, yi - radius, 2 * radius + 1, 2 * radius + 1)


def is_cell_colour(rgb: np.ndarray) -> np.ndarray:
    """The cells' ramp (YlOrRd) is warm, even under their dark outlines; the globe, graticule and space
    are dark and blue."""
    r, b = rgb[..., 0].astype(int), rgb[..., 2].astype(int)
    return (r > 80) & (r > b + 30)


def legend(driver: Any) -> list[dict[str, Any]]:
    """The legend's classes, lowest first: colour, from, to (as numbers) and the text shown."""
    return [
        {"colour": li.get_attribute("data-colour"), "from": float(li.get_attribute("data-from")),
         "to": float(li.get_attribute("data-to")), "text": li.text}
        for li in driver.find_elements(By.CSS_SELECTOR, "#legend-steps li")
    ]


RAMP = ["#ffffb2", "#fed976", "#feb24c", "#fd8d3c", "#fc4e2a", "#e31a1c", "#b10026"]  # app.js's RAMP
CELL_OPACITY = 0.8  # app.js's cells' fill-opacity


#: An async script's frame: the screenshot (arguments[0], base64 PNG) decoded into `d` (RGBA bytes) and `img`, then
#: the body given with `%`, which calls `done` (`g` is the canvas's context); arguments[1] (`points`) is the body's own.
_DECODED_SCREENSHOT = """
        const [png, points, done] = arguments;
        const img = new Image();
        img.onload = () => {
          const c = document.createElement('canvas');
          c.width = img.width; c.height = img.height;
          const g = c.getContext('2d', {willReadFrequently: true});
          g.drawImage(img, 0, 0);
          const d = g.getImageData(0, 0, img.width, img.height).data;
          %s
        };
        img.onerror = () => done(null);
        img.src = 'data:image/png;base64,' + png;
"""


def pixels_at(driver: Any, points: list[tuple[float, float]]) -> np.ndarray:
    """The RGB pixels of a screenshot at page points (x, y), (n, 3)."""
    script = _DECODED_SCREENSHOT % """
          done(points.map(([x, y]) => { const i = 4 * (Math.round(y) * img.width + Math.round(x));
                                         return [d[i], d[i + 1], d[i + 2]]; }));"""
    result = driver.execute_async_script(script, driver.get_screenshot_as_base64(), points)
    assert result is not None, "the screenshot did not decode"
    return np.array(result, float).reshape(-1, 3)


def rendered_colours(driver: Any) -> list[str]:
    """The colour class drawn at the centre of each cell on the map that is on the globe's near side and in the
    window (read from a screenshot): the ramp colour whose blend (app.js's opacity) over the land or the sea is
    nearest the pixel. The cells' own list (zone ids) comes from the page; their centres from dggs."""
    zones = [c["zone_id"] for c in driver.execute_script("return window.dggsDrawnCells()")]
    lat, lng = dggs.cell_to_latlng(zones)
    points = driver.execute_script(
        """const [lat, lng] = arguments, m = window.dggsMap, r = m.getCanvas().getBoundingClientRect();
           return lat.map((y, i) => { const p = m.project([lng[i], y]), q = m.unproject(p), back = m.project(q);
             const near = Math.hypot(back.x - p.x, back.y - p.y) < 1 && Math.abs(q.lat - y) < 1e-3;
             return near && p.x > 2 && p.y > 2 && p.x < r.width - 2 && p.y < r.height - 2 ? [r.left + p.x, r.top + p.y] : null; });""",
        list(np.asarray(lat, float)), list(np.asarray(lng, float)))
    shown = [p for p in points if p is not None]
    rgb = pixels_at(driver, shown)
    ramp = np.array([[int(c[i:i + 2], 16) for i in (1, 3, 5)] for c in RAMP], float)
    under = np.array([LAND_COLOUR, SEA_COLOUR], float)
    blends = CELL_OPACITY * ramp[:, None, :] + (1 - CELL_OPACITY) * under[None, :, :]  # (7, 2, 3)
    dist = np.linalg.norm(rgb[:, None, None, :] - blends[None], axis=-1).min(axis=2)  # (n, 7)
    return [RAMP[k] for k in dist.argmin(axis=1)]


def level_rows(path: Path, level: int, column: str | None = None, stats: tuple[str, ...] = ("count",)) -> list[dict]:
    with CellStore(path) as store:
        return store.aggregate(level, column, stats)


# --- Tests ------------------------------------------------------------------------------------------
def test_page_loads_without_errors(page: Any, server: str) -> None:
    s = state(page)
    assert s["body"] == "idle", s
    assert s["lastError"] is None
    assert s["featureCount"] > 0 and 0 <= s["level"] <= STORED_LEVEL
    assert "dggs" in page.title
    assert js_errors(page) == []
    # Everything came from this server: no request left 127.0.0.1.
    urls = page.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    assert urls and all(u.startswith(server) or u.startswith(("blob:", "data:")) for u in urls), urls
    assert page.execute_script("return window.dggsMap.getProjection().type") == "globe"
    # Labelled, focusable controls.
    for select_id in ("column", "stat", "level", "scale"):
        assert page.find_element(By.CSS_SELECTOR, f"label[for={select_id}]").text
    # The keyboard reaches the controls, then the map (the stat select is disabled for the row count).
    page.execute_script("document.activeElement.blur()")
    reached = []
    for _ in range(8):
        ActionChains(page).send_keys(Keys.TAB).perform()
        active = page.switch_to.active_element
        reached.append(active.get_attribute("id") or active.get_attribute("class"))
    assert reached[:3] == ["column", "level", "scale"], reached
    assert any("maplibregl-canvas" in r for r in reached), reached
    options = [o.get_attribute("value") for o in Select(page.find_element(By.ID, "column")).options]
    assert options == ["", "pop"]


def test_cells_drawn_where_the_data_is(page: Any, data: dict[str, Any]) -> None:
    if state(page)["column"] is not None:
        choose(page, "column", "")
    s = set_view(page, GLOBE_VIEW)
    assert s["bbox"] == [-180, -90, 180, 90], "the whole globe is in view: the whole world is fetched"
    # All non-empty cells of the level, rolled up by the server.
    rows = level_rows(data["path"], s["level"])
    assert s["featureCount"] == len(rows)
    assert s["max"] == max(r["count"] for r in rows)
    shot = Screenshot(page)
    for lat, lng in [EUROPE, AFRICA]:
        x, y = project(page, lat, lng)
        assert 0 < x < WIDTH and 0 < y < HEIGHT
        pixels = shot.patch(x, y)
        assert is_cell_colour(pixels).mean() > 0.8, (lat, lng, pixels.tolist())
    assert shot.size == (WIDTH, HEIGHT)
    for lat, lng in EMPTY:
        x, y = project(page, lat, lng)
        assert 0 < x < WIDTH and 0 < y < HEIGHT
        pixels = shot.patch(x, y, 4)
        assert not is_cell_colour(pixels).any(), (lat, lng, pixels.tolist())
    # Nothing is drawn in space, below the globe.
    assert not is_cell_colour(shot.region(WIDTH // 2 - 200, HEIGHT - 20, 400, 20)).any()
    assert js_errors(page) == []


def test_zoom_in_shows_finer_cells(page: Any, data: dict[str, Any]) -> None:
    coarse = set_view(page, GLOBE_VIEW)
    coarse_area = page.execute_script("return window.dggsDrawnCells()[0].area_km2")
    fine = set_view(page, EUROPE_VIEW)
    assert fine["level"] > coarse["level"]
    assert fine["featureCount"] > coarse["featureCount"]
    w, s, e, n = fine["bbox"]
    assert -180 < w < EUROPE[1] < e < 180 and -90 < s < EUROPE[0] < n < 90, fine["bbox"]
    areas = page.execute_script(
        "return window.dggsDrawnCells().slice(0, 20).map(c => c.area_km2)"
    )
    expected = dggs.cell_area(dggs.latlng_to_cell(*EUROPE, fine["level"]), "km^2")
    assert areas and all(a == pytest.approx(expected, rel=1e-6) for a in areas)
    assert expected < coarse_area / 3 ** (fine["level"] - coarse["level"] - 0.5)
    assert js_errors(page) == []


def test_click_on_a_cell_shows_its_id(page: Any, data: dict[str, Any]) -> None:
    from dggs.server.reader import map_densify

    s = set_view(page, EUROPE_VIEW)
    level = s["level"]
    # A cell with data near the view's centre; click its centre.
    near = np.argmin((data["lat"] - EUROPE[0]) ** 2 + (data["lng"] - EUROPE[1]) ** 2)
    cell = dggs.latlng_to_cell(float(data["lat"][near]), float(data["lng"][near]), level)
    lat, lng = dggs.cell_to_latlng(cell)
    x, y = project(page, lat, lng)
    canvas = page.find_element(By.CSS_SELECTOR, "#map canvas")
    rect = canvas.rect
    ActionChains(page).move_to_element_with_offset(
        canvas, int(round(x - rect["x"] - rect["width"] / 2)), int(round(y - rect["y"] - rect["height"] / 2))
    ).click().perform()
    info = wait_for(page, lambda: page.find_elements(By.CSS_SELECTOR, ".maplibregl-popup .cell-info"))[0]
    zone_id = info.find_element(By.CSS_SELECTOR, "[data-field=zone_id]").text
    assert zone_id == dggs.latlng_to_cell(lat, lng, level) == cell
    assert info.get_attribute("data-zone-id") == cell
    assert info.find_element(By.CSS_SELECTOR, "[data-field=level]").text == str(level)
    area = float(info.find_element(By.CSS_SELECTOR, "[data-field=area_km2]").text.split()[0].replace(",", ""))
    assert area == pytest.approx(dggs.cell_area(cell, "km^2"), rel=1e-3)
    rows = int(info.find_element(By.CSS_SELECTOR, "[data-field=count]").text.replace(",", ""))
    in_cell = dggs.latlng_to_cell(data["lat"], data["lng"], level) == cell
    assert rows == int(in_cell.sum()) > 0
    # The zone's description from the OGC API adds its centre.
    wait_for(page, lambda: info.get_attribute("data-info") == "loaded", message="zone info not shown")
    assert state(page)["selected"] == cell
    # Drawn from ids, the cell is outlined by the layer (its outline with 8 times map_densify's points).
    outlined = "return window.dggsCellsLayer.selected && window.dggsCellsLayer.selected.count"
    assert state(page)["source"] != "ids" or page.execute_script(outlined) == 2 * 3 * 8 * (1 + map_densify(level))
    assert js_errors(page) == []
    # Close it for the next test.
    info.find_element(By.XPATH, "./..").find_element(By.CSS_SELECTOR, ".maplibregl-popup-close-button").click()
    wait_for(page, lambda: not page.find_elements(By.CSS_SELECTOR, ".maplibregl-popup"))
    assert not page.execute_script(outlined)


def test_value_select_recolours(page: Any, data: dict[str, Any]) -> None:
    if state(page)["column"] is not None:
        choose(page, "column", "")
    s = set_view(page, GLOBE_VIEW)
    level = s["level"]
    count_max = max(r["count"] for r in level_rows(data["path"], level))
    assert legend(page)[-1]["to"] == count_max
    paint_before = page.execute_script("return window.dggsCellPaint()")

    s = choose(page, "column", "pop")
    assert (s["column"], s["stat"]) == ("pop", "sum")
    sums = level_rows(data["path"], level, "pop", ("count", "sum"))
    assert legend(page)[-1]["to"] == max(r["sum"] for r in sums) != count_max
    assert page.find_element(By.ID, "legend-title").text == "sum of pop"
    assert page.find_element(By.ID, "legend-level").text == f"level {level}"
    paint_after = page.execute_script("return window.dggsCellPaint()")
    assert paint_after != paint_before

    s = choose(page, "stat", "max")
    assert legend(page)[-1]["to"] == int(data["pop"].max())
    assert s["featureCount"] == len(sums)
    assert js_errors(page) == []
    choose(page, "column", "")


def test_too_many_cells_steps_to_a_coarser_level(page: Any, data: dict[str, Any]) -> None:
    set_view(page, GLOBE_VIEW)
    assert len(level_rows(data["path"], STORED_LEVEL)) > MAX_FEATURES
    try:
        s = choose(page, "level", str(STORED_LEVEL))
        assert s["lastError"] is None
        assert s["level"] < STORED_LEVEL
        assert s["featureCount"] == len(level_rows(data["path"], s["level"])) <= MAX_FEATURES
        assert page.find_element(By.ID, "status").text.startswith(f"level {s['level']} ")
        assert js_errors(page) == []
    finally:
        choose(page, "level", "auto")


def test_land_is_drawn_under_the_cells(page: Any) -> None:
    assert state(page)["geography"] == "loaded"
    set_view(page, GLOBE_VIEW)
    counts = page.execute_script(
        "return ['land', 'coastline', 'borders'].map(id => window.dggsMap.queryRenderedFeatures({layers: [id]}).length)"
    )
    assert all(n > 0 for n in counts), counts
    order = page.execute_script("return window.dggsMap.getStyle().layers.map(l => l.id)")
    assert max(order.index(n) for n in ("land", "coastline", "borders")) < order.index("cells-fill"), order
    # On screen: land (no cells there) in the land colour, the open sea in the sea's.
    shot = Screenshot(page)
    land = shot.patch(*project(page, *ARABIA)).reshape(-1, 3).mean(axis=0)
    sea = shot.patch(*project(page, *EMPTY[0])).reshape(-1, 3).mean(axis=0)
    assert np.abs(land - LAND_COLOUR).max() < 8, land
    assert np.abs(sea - SEA_COLOUR).max() < 8, sea
    assert js_errors(page) == []


# Deep inside Antarctica's ice sheet (away from the ice shelves, which Natural Earth leaves as sea, and from the
# graticule's 30-degree lines), two of them beyond 85 S where Web Mercator, and so MapLibre's tiles, end.
ANTARCTICA = [(-80.0, 15.0), (-80.0, 105.0), (-75.0, 135.0), (-82.0, -110.0), (-87.0, 45.0), (-88.0, -135.0)]
SOUTH_VIEW = {"center": [0.0, -70.0], "zoom": 0.0}  # MapLibre scales the globe by 1 / cos(lat)


def test_antarctica_is_land_to_the_pole(page: Any) -> None:
    # world-atlas writes it as a polar ring with the coast as a hole; app.js closes the coast through the pole
    set_view(page, SOUTH_VIEW)
    shot = Screenshot(page)
    positions = {p: project(page, *p) for p in ANTARCTICA}
    assert all(0 < x < WIDTH and 0 < y < HEIGHT for x, y in positions.values()), positions
    colours = {p: shot.patch(*project(page, *p)).reshape(-1, 3).mean(axis=0) for p in ANTARCTICA}
    off = {p: c.round() for p, c in colours.items() if np.abs(c - LAND_COLOUR).max() >= 8}
    assert not off, off
    sea = shot.patch(*project(page, -50.0, -20.0)).reshape(-1, 3).mean(axis=0)  # the Southern Ocean stays sea
    assert np.abs(sea - SEA_COLOUR).max() < 8, sea
    assert js_errors(page) == []


# The largest countries by area (Natural Earth's names); the labels name the LABEL_COUNT largest.
LARGEST = ["Russia", "Antarctica", "Canada", "United States of America", "China", "Brazil", "Australia", "India"]


def test_country_labels_name_the_land_under_them_while_zoomed_out(page: Any) -> None:
    set_view(page, GLOBE_VIEW)
    labels = page.execute_script("return window.dggsLabels.map(l => ({name: l.name, lng: l.lng, lat: l.lat}))")
    names = [label["name"] for label in labels]
    assert set(LARGEST) <= set(names) and len(names) == len(set(names)) >= 20, names
    # Each label stands on its own country: the land MapLibre drew under the label's point has its name.
    under = page.execute_script(
        "return window.dggsLabels.map(l => { const p = window.dggsMap.project([l.lng, l.lat]);"
        " return window.dggsMap.queryRenderedFeatures(p, {layers: ['land']}).map(f => f.properties.name); })"
    )
    visible = page.execute_script(
        "return window.dggsLabels.map(l => getComputedStyle(l.element).display !== 'none'"
        " && Number(getComputedStyle(l.element).opacity) > 0)"
    )
    front = [label for label, names_under, shown in zip(labels, under, visible, strict=True) if shown]
    assert len(front) >= 5, labels  # the globe's near side has labels showing
    for label, names_under, shown in zip(labels, under, visible, strict=True):
        if shown:
            assert label["name"] in names_under, (label, names_under)
    shown_names = [label["name"] for label in front]
    assert "Russia" in shown_names and "Australia" not in shown_names  # the far side's are hidden
    # Zoomed in, none.
    set_view(page, EUROPE_VIEW)
    hidden = page.execute_script(
        "return window.dggsLabels.every(l => getComputedStyle(l.element).display === 'none')")
    assert hidden
    set_view(page, GLOBE_VIEW)
    assert js_errors(page) == []


def test_a_skewed_column_spreads_over_the_colour_classes(page: Any, data: dict[str, Any]) -> None:
    set_view(page, GLOBE_VIEW)
    s = choose(page, "column", "pop")
    try:
        if s["stat"] != "sum":  # the menu keeps what an earlier test chose
            s = choose(page, "stat", "sum")
        assert (s["stat"], s["scale"]) == ("sum", "quantile")
        sums = sorted(r["sum"] for r in level_rows(data["path"], s["level"], "pop", ("count", "sum")))
        assert sums[-1] > 10 * sums[len(sums) // 2], "the sums are skewed"
        steps = legend(page)
        assert len(steps) == 7 and steps[0]["from"] == sums[0] and steps[-1]["to"] == sums[-1]
        assert all(a["to"] == b["from"] for a, b in zip(steps, steps[1:], strict=False))
        assert f"level {s['level']}" == page.find_element(By.ID, "legend-level").text
        # The colours MapLibre drew: quantile classes, each holding a fair share of the cells.
        colours = rendered_colours(page)
        shares = sorted((colours.count(c) / len(colours) for c in set(colours)), reverse=True)
        assert len(shares) >= 4 and shares[0] < 0.3, shares
        target = os.environ.get("DGGS_SCREENSHOT")  # the picture in the docs
        if target:
            page.execute_script("document.activeElement.blur()")
            Path(target).parent.mkdir(parents=True, exist_ok=True)
            Path(target).write_bytes(page.get_screenshot_as_png())
        # Linear classes on the same sums leave most cells in the palest class; logarithmic ones do not.
        choose(page, "scale", "linear")
        linear = rendered_colours(page)
        assert max(linear.count(c) for c in set(linear)) / len(linear) > 0.5
        choose(page, "scale", "log")
        log = rendered_colours(page)
        assert len(set(log)) >= 4
        bounds = [step["to"] for step in legend(page)[:-1]]
        ratios = [b / a for a, b in zip(bounds, bounds[1:], strict=False)]
        assert max(ratios) / min(ratios) < 1.2, bounds  # equal ratios, up to rounding
        assert js_errors(page) == []
    finally:
        if state(page)["scale"] != "quantile":
            choose(page, "scale", "quantile")
        if state(page)["column"] is not None:
            choose(page, "column", "")


# --- Cells from ids (issue 34) ---------------------------------------------------------------------
def _unit(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    """Points of the unit sphere, (n, 3), in MapLibre's frame (x = sin lng cos lat, y = sin lat, z = cos lng cos lat)."""
    la, lo = np.radians(lat), np.radians(lng)
    return np.stack([np.sin(lo) * np.cos(la), np.sin(la), np.cos(lo) * np.cos(la)], axis=-1)


def _in_triangles(tri: dict[str, Any], points: np.ndarray) -> np.ndarray:
    """Which points (unit vectors) the layer's triangles cover: the triangles are chords of the sphere, so a
    point is on one where it is on the same side of the three planes through the sphere's centre and an edge."""
    v = np.asarray(tri["lnglat"], float).reshape(-1, 3)
    xyz = _unit(v[:, 1], v[:, 0])
    idx = np.asarray(tri["index"], int).reshape(-1, 3)
    a, b, c = xyz[idx[:, 0]], xyz[idx[:, 1]], xyz[idx[:, 2]]
    orient = np.sign(np.einsum("ij,ij->i", np.cross(a, b), c))[:, None]
    inside = (orient != 0) & ((a + b + c) @ points.T > 0)  # degenerate triangles cover nothing; nor antipodes
    for p, q in ((a, b), (b, c), (c, a)):
        inside &= (np.cross(p, q) @ points.T) * orient >= 0
    return np.asarray(inside.any(axis=0))


# Zones whose drawing the tests check: the poles' and the antimeridian's cells at every level the map shows
# them with another number of points an edge (8: levels 0-2, 4: 3-5, 2: 6 on), and the whole of levels 0-1.
def _zones_to_check() -> list[tuple[str, int]]:
    zones = [(str(z), 0) for z in dggs.get_base_cells()]
    zones += [(str(z), 1) for z in dggs.uncompact_cells(list(dggs.get_base_cells()), 1)]
    for level in (2, 4, 7, 10):
        near = {str(dggs.latlng_to_cell(lat, lng, level)) for lat in (90, -90, 89.9, -89.9, 0, 45, -60)
                for lng in (180, -180, 179.99, -179.99, 0)}
        zones += [(z, level) for z in sorted(near)]
    return zones


def test_the_layers_triangles_cover_the_ground_of_the_geojson(page: Any) -> None:
    """The WebGL layer's triangles for a cell (from its id, with the WebAssembly core) cover the ground of the
    server's GeoJSON polygon of it (dggs.cell_to_polygon with map_densify's points an edge, split at the
    antimeridian): at random points round each cell, at the poles and across the antimeridian among them,
    the triangles and the polygon agree but within 1 % of the cell's size from its outline (where the chords
    between the outline's points and the polygon's straight lng/lat edges part)."""
    import shapely
    from shapely.geometry import Point

    from dggs.server.reader import map_densify

    rng = np.random.default_rng(34)
    checked = 0
    by_level: dict[int, list[str]] = {}
    for zone, level in _zones_to_check():
        by_level.setdefault(level, []).append(zone)
    for level, zones in by_level.items():
        tris = page.execute_async_script(
            "const [zones, level, done] = arguments; window.dggsCellTriangles(zones, level).then(done);", zones, level)
        assert [t["zone"] for t in tris] == zones  # one chunk a cell
        for zone, tri in zip(zones, tris, strict=True):
            polygon = dggs.cell_to_polygon(zone, densify=map_densify(level))
            shapely.prepare(polygon)
            size = np.degrees(np.sqrt(dggs.cell_area(zone, "rads^2")))
            clat, clng = dggs.cell_to_latlng(zone)
            # 400 points in a cap of twice the cell's size round its centre.
            centre = _unit(np.array([clat]), np.array([clng]))[0]
            ortho = np.cross(centre, [0.3, 0.5, 0.8])
            ortho /= np.linalg.norm(ortho)
            other = np.cross(centre, ortho)
            r = np.radians(2 * size) * np.sqrt(rng.uniform(0, 1, 400))
            t = rng.uniform(0, 2 * np.pi, 400)
            pts = (np.cos(r)[:, None] * centre + np.sin(r)[:, None] * (np.cos(t)[:, None] * ortho
                                                                         + np.sin(t)[:, None] * other))
            lat, lng = np.degrees(np.arcsin(np.clip(pts[:, 1], -1, 1))), np.degrees(np.arctan2(pts[:, 0], pts[:, 2]))
            ours = _in_triangles(tri, pts)
            theirs = shapely.contains_xy(polygon, lng, lat)
            assert ours.any() and theirs.any(), zone
            for k in np.flatnonzero(ours != theirs):
                off = polygon.boundary.distance(Point(lng[k], lat[k]))
                # Near a pole a degree of longitude is short: measure along the parallel there.
                assert off < 0.01 * size / max(np.cos(np.radians(lat[k])), 0.01), (zone, level, lat[k], lng[k], off)
            checked += 1
    assert checked == len(_zones_to_check())


def test_a_whole_level_is_built_into_buffers_that_tile_the_sphere(page: Any) -> None:
    """Every cell of level 7 (87,480; the benchmark draws 1M of level 10) goes into the layer's 16-bit buffer
    chunks: each cell's fan (its centre and 9 outline points, 9 triangles), and the triangles' spherical areas
    add up to the sphere's, 4 pi (an independent sum: l'Huilier's theorem by way of the triple product)."""
    got = page.execute_async_script(
        """const done = arguments[0];
           (async () => {
             const core = await import('/static/vendor/dggs/dggs.js');
             const { cellChunks } = await import('/static/cells_layer.js');
             const all = new Set();
             for (const lat of [-80, -50, -20, 0, 20, 50, 80, 90, -90]) for (let lng = -180; lng < 180; lng += 10)
               all.add(core.latLngToCell(lat, lng, 0, { asBigInt: true }));
             const ids = core.uncompactCells(BigUint64Array.from(all), 7, { asBigInt: true });
             const cells = BigUint64Array.from(ids);
             let area = 0, vertices = 0, indices = 0, chunks = 0, built = 0, big = 0;
             const DEG = Math.PI / 180;
             for await (const c of cellChunks(core, cells, new Float64Array(cells.length), { densify: 2, projection: 'ISEA' })) {
               chunks += 1; built += c.cells; vertices += c.lnglat.length / 3; indices += c.index.length;
               if (c.lnglat.length / 3 > 65536) big += 1;
               const P = (i) => { const x = c.lnglat[3 * i] * DEG, y = c.lnglat[3 * i + 1] * DEG;
                                  return [Math.sin(x) * Math.cos(y), Math.sin(y), Math.cos(x) * Math.cos(y)]; };
               for (let t = 0; t < c.index.length; t += 3) {
                 const a = P(c.index[t]), b = P(c.index[t + 1]), d = P(c.index[t + 2]);
                 const det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) + a[2] * (b[0] * d[1] - b[1] * d[0]);
                 const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
                 area += 2 * Math.atan2(det, 1 + dot(a, b) + dot(b, d) + dot(d, a));
               }
             }
             done({ n: cells.length, base: all.size, area, vertices, indices, chunks, built, big });
           })().catch((e) => done({ error: String(e) }));""")
    assert "error" not in got, got
    assert got["base"] == 20 and got["n"] == got["built"] == dggs.get_num_cells(7) == 87_480
    assert got["vertices"] == 10 * got["n"] and got["indices"] == 27 * got["n"]
    assert got["big"] == 0 and got["chunks"] >= got["vertices"] / 65536
    assert abs(got["area"]) == pytest.approx(4 * np.pi, rel=1e-9)


def test_cells_are_drawn_from_ids_by_default(page: Any, server: str) -> None:
    """The page asks for ids (map/cells?f=uint64) and draws them with the WebAssembly core and the WebGL layer:
    the same cells as the GeoJSON answer for the view on the map, and no GeoJSON on the map."""
    s = set_view(page, EUROPE_VIEW)
    assert s["source"] == "ids", s
    urls = page.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    cells = [u for u in urls if "/map/cells?" in u]
    assert cells and all("f=uint64" in u for u in cells), cells
    assert any(u.endswith("/vendor/dggs/dggs.wasm") for u in urls)
    drawn = page.execute_script("return window.dggsDrawnZones()")
    bbox = ",".join(str(x) for x in s["bbox"])
    doc = _get_json(f"{server}/map/cells?level={s['level']}&bbox={bbox}&stat=count")
    assert drawn == [f["properties"]["zone_id"] for f in doc["features"]] and len(drawn) == s["featureCount"] > 0
    layer = page.execute_script("return [window.dggsMap.getLayer('cells-ids').type, window.dggsCellsLayer.stats]")
    assert layer[0] == "custom" and layer[1]["cells"] == len(drawn) and layer[1]["chunks"] >= 1
    assert page.execute_script("return window.dggsMap.getSource('cells').serialize().data.features.length") == 0
    assert js_errors(page) == []


def cell_mask(driver: Any) -> np.ndarray:
    """Which pixels of a screenshot of the page show a cell (is_cell_colour's test, made in the page), (H, W)."""
    script = _DECODED_SCREENSHOT % """
          let bits = '';
          for (let i = 0; i < d.length; i += 4) bits += d[i] > 80 && d[i] > d[i + 2] + 30 ? '1' : '0';
          done([img.width, img.height, bits]);"""
    driver.execute_script("document.activeElement.blur()")
    got = driver.execute_async_script(script, driver.get_screenshot_as_base64(), None)
    assert got is not None, "the screenshot did not decode"
    return (np.frombuffer(got[2].encode(), np.uint8) == ord("1")).reshape(got[1], got[0])


def _same_cell_pixels(ids_mask: np.ndarray, geojson_mask: np.ndarray) -> float:
    """The share of the GeoJSON picture's cell pixels on which the two pictures differ, leaving out a pixel next
    to a cell's edge (within 1 px in the GeoJSON picture): MapLibre antialiases the GeoJSON cells' edges and
    draws their outlines, so those may go either way."""
    padded = np.pad(geojson_mask, 1, mode="edge")
    shifted = [padded[1 + dy:padded.shape[0] - 1 + dy, 1 + dx:padded.shape[1] - 1 + dx]
               for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
    edge = np.any(shifted, axis=0) & ~np.all(shifted, axis=0)
    return float((np.logical_xor(ids_mask, geojson_mask) & ~edge).sum() / max(geojson_mask.sum(), 1))


# The views the two ways are compared on: the globe, the globe turning flat (MapLibre's globe goes to Web
# Mercator between zooms 10 and 12: the layer's vertices then go through its fallback matrix too), and flat.
PIXEL_VIEWS = [EUROPE_VIEW, {"center": [EUROPE[1], EUROPE[0]], "zoom": 11.0},
               {"center": [EUROPE[1], EUROPE[0]], "zoom": 12.5}]


def test_cells_as_geojson_where_asked(page: Any, server: str) -> None:
    """With ?cells=geojson (as where the WebAssembly core is missing) the page draws the server's GeoJSON: the
    same cells as from ids, on the same pixels (the screenshots' cell-coloured pixels differ on under 0.2 % of
    them, away from the cells' edges), on the globe, while it turns flat and flat. Last: it leaves the page
    reloaded as the other tests had it."""
    try:
        from_ids = [set_view(page, view) for view in PIXEL_VIEWS[:1]]
        ids_drawn = page.execute_script("return window.dggsDrawnZones()")
        ids_masks = [cell_mask(page)]
        for view in PIXEL_VIEWS[1:]:
            from_ids.append(set_view(page, view))
            ids_masks.append(cell_mask(page))
        page.get(f"{server}/?cells=geojson")
        wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))
        s = set_view(page, PIXEL_VIEWS[0])
        assert s["source"] == "geojson" and s["level"] == from_ids[0]["level"], s
        urls = page.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        cells = [u for u in urls if "/map/cells?" in u]
        assert cells and not any("f=uint64" in u for u in cells), cells
        assert not any("/vendor/dggs/" in u for u in urls)
        drawn = page.execute_script(
            "return window.dggsMap.getSource('cells').serialize().data.features.map(f => f.properties.zone_id)")
        assert drawn == ids_drawn and len(drawn) > 0
        for k, view in enumerate(PIXEL_VIEWS):
            if k:
                s = set_view(page, view)
                assert s["level"] == from_ids[k]["level"], (view, s)
            geojson_mask = cell_mask(page)
            off = _same_cell_pixels(ids_masks[k], geojson_mask)
            assert ids_masks[k].sum() > 0.05 * ids_masks[k].size and off < 0.002, (view, off)
        assert js_errors(page) == []
    finally:
        page.get(f"{server}/")
        wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))


@pytest.fixture(scope="module")
def polar_server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """`dggs serve` of a store with cells round the north pole (latitudes 65-90) and along the antimeridian
    (latitudes -25 to 25 within 12 degrees of it), level 6, the pole's own cell among them."""
    rng = np.random.default_rng(90)
    n = 300  # some 680 cells of level 6 in the cap, 420 in the band: about a third hold a point, so the tests'
    # pictures have empty cells among full ones (a boundary between two full cells shows nothing)
    lat = np.concatenate([np.degrees(np.arcsin(rng.uniform(np.sin(np.radians(65)), 1, n))), rng.uniform(-25, 25, n),
                          [90.0]])
    lng = np.concatenate([rng.uniform(-180, 180, n), (rng.uniform(168, 192, n) + 180) % 360 - 180, [0.0]])
    path = tmp_path_factory.mktemp("polar-store") / "cells.db"
    with CellStore(path) as store:
        store.ingest_points(lat, lng, 6, {"v": rng.integers(1, 100, lat.size)})
    port = free_port()
    proc = subprocess.Popen(_serve_command(path, port), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + TIMEOUT
        while True:
            try:
                _get_json(f"{base}/map/layers", timeout=2.0)
                break
            except (OSError, urllib.error.URLError):
                if time.monotonic() > deadline or proc.poll() is not None:
                    pytest.fail("the polar store's dggs serve did not answer")
                time.sleep(0.1)
        yield base
    finally:
        proc.terminate()
        proc.wait(10)


def _mask_of(page: Any, url: str) -> tuple[np.ndarray, dict[str, Any]]:
    page.get("about:blank")
    page.get(url)
    wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))
    wait_for(page, lambda: page.execute_script("return window.dggsState.geography") != "loading")
    s = state(page)
    assert s["body"] == "idle" and s["featureCount"] > 0, s
    return cell_mask(page), s


@pytest.mark.parametrize(("view", "polar"),
                         [("2.2/80/30", True), ("2.4/88/30", True), ("2.6/0/180", False), ("2.6/5/-179", False)])
def test_ids_and_geojson_cover_the_same_pixels_at_the_pole_and_the_antimeridian(
        page: Any, server: str, polar_server: str, view: str, polar: bool) -> None:
    """Round the north pole and across the antimeridian, the cells drawn from ids by the WebGL layer (in 3D) show
    where dggs.latlng_to_cell of a pixel's point is a drawn cell (every pixel of a grid on the globe, but within
    2 px of a cell's edge), the pole among them; and across the antimeridian the server's GeoJSON polygons
    drawn by MapLibre (split there) cover the same pixels but for 0.5 % of them away from the cells' edges.
    Round the pole they do not: beyond latitude 85, where MapLibre's Web Mercator tiles end, its GeoJSON fills
    part from the cells, and latlng_to_cell sides with the ids. Last: it leaves the module's page loaded as the
    other tests had it."""
    try:
        ids_mask, from_ids = _mask_of(page, f"{polar_server}/#{view}")
        # The oracle: a pixel shows a cell where the cell of its point (dggs.latlng_to_cell at the shown level)
        # is one of the drawn cells; checked on a grid of pixels on the globe, away from the cells' edges.
        drawn = set(page.execute_script("return window.dggsDrawnZones()"))
        ys, xs = np.mgrid[12:ids_mask.shape[0] - 12:16, 300:ids_mask.shape[1] - 60:16]  # not under the legend
        points = page.execute_script(
            """const m = window.dggsMap;
               return arguments[0].map(([x, y]) => { const q = m.unproject([x, y]), p = m.project(q);
                 return Math.hypot(p.x - x, p.y - y) < 0.5 ? [q.lat, q.lng] : null; });""",
            np.stack([xs.ravel(), ys.ravel()], axis=1).tolist())
        window = ids_mask[ys.ravel()[:, None, None] + np.arange(-2, 3)[None, :, None],
                          xs.ravel()[:, None, None] + np.arange(-2, 3)[None, None, :]]
        inner = window.all(axis=(1, 2)) | ~window.any(axis=(1, 2))
        on_globe = np.array([p is not None for p in points])
        keep = np.flatnonzero(on_globe & inner)
        cells = dggs.latlng_to_cell([points[k][0] for k in keep], [points[k][1] for k in keep], from_ids["level"])
        oracle = np.array([str(c) in drawn for c in cells])
        shown = ids_mask[ys.ravel()[keep], xs.ravel()[keep]]
        assert len(keep) > 200 and oracle.any() and (shown == oracle).all(), (view, int((shown != oracle).sum()))
        if polar:  # latitudes beyond 85 on the screen (the pole too, in the second view)
            assert page.execute_script("return window.dggsMap.unproject([500, 5]).lat") > 85
        geojson_mask, from_geojson = _mask_of(page, f"{polar_server}/?cells=geojson#{view}")
        assert (from_ids["source"], from_geojson["source"]) == ("ids", "geojson")
        assert from_ids["level"] == from_geojson["level"] and from_ids["featureCount"] == from_geojson["featureCount"]
        off = _same_cell_pixels(ids_mask, geojson_mask)
        assert ids_mask.sum() > 0.01 * ids_mask.size, view
        # Beyond latitude 85 MapLibre's GeoJSON fills part from the cells (9 % of the cell pixels in the first
        # view, where latlng_to_cell sides with the ids): no bound on them there.
        assert polar or off < 0.005, (view, from_ids["level"], off)
        assert js_errors(page) == []
    finally:
        page.get(f"{server}/")
        wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))
        wait_for(page, lambda: page.execute_script("return window.dggsState.geography") != "loading")


def test_where_the_webgl_layer_cannot_draw_the_cells_come_as_geojson(page: Any, server: str) -> None:
    """A layer whose shaders fail (as where WebGL lacks what it needs: here its program() is made to throw) hands
    the map back to GeoJSON: the page asks map/cells for GeoJSON and MapLibre draws the same cells. Last: it
    leaves the page reloaded as the other tests had it."""
    try:
        s = set_view(page, EUROPE_VIEW)
        assert s["source"] == "ids"
        ids_drawn = page.execute_script("return window.dggsDrawnZones()")
        before = s["renders"]
        page.execute_script("""const layer = window.dggsCellsLayer;
            layer.programs.clear();
            layer.program = () => { throw new Error('no shader here (test)'); };
            window.dggsMap.triggerRepaint();""")
        wait_for(page, lambda: state(page)["source"] == "geojson", message="the page did not fall back to GeoJSON")
        s = settle(page, before)
        drawn = page.execute_script(
            "return window.dggsMap.getSource('cells').serialize().data.features.map(f => f.properties.zone_id)")
        assert drawn == ids_drawn and s["featureCount"] == len(drawn) > 0
        assert page.execute_script("return window.dggsMap.getLayer('cells-ids')") is None
        urls = page.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        assert "f=uint64" not in [u for u in urls if "/map/cells?" in u][-1]
        assert js_errors(page) == []
    finally:
        page.get(f"{server}/")
        wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))


def test_the_standalone_page_of_docs_js_draws_cells_from_ids(page: Any, data: dict[str, Any], server: str,
                                                              tmp_path: Path) -> None:
    """docs/js.md's page, saved in a copy of the web map's folder and served by create_app(static=...), draws
    the store's level-3 cells from ids. Last: it leaves the page reloaded as the other tests had it."""
    import re
    import shutil
    import threading

    import uvicorn

    from dggs.server.app import create_app
    from dggs.server.vendor import STATIC_FOLDER

    html = re.search(r"^```html\n(.*?)^```", (Path(__file__).parents[2] / "docs/js.md").read_text(), re.M | re.S)
    assert html is not None
    folder = tmp_path / "static"
    shutil.copytree(STATIC_FOLDER, folder)
    (folder / "cells.html").write_text(html.group(1))
    port = free_port()
    srv = uvicorn.Server(uvicorn.Config(create_app(data["path"], static=folder), host="127.0.0.1", port=port,
                                        log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    try:
        wait_for(page, lambda: srv.started, message="the second server did not start")
        page.get(f"http://127.0.0.1:{port}/static/cells.html")
        drawn = wait_for(page, lambda: page.execute_script("return window.cellsDrawn"), message="no cells drawn")
        assert drawn == len(level_rows(data["path"], 3)) > 0
        assert js_errors(page) == []
    finally:
        srv.should_exit = True
        thread.join(10)
        page.get(f"{server}/")
        wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))


def test_the_view_is_in_the_url_and_a_link_opens_it(page: Any, server: str) -> None:
    """Issue 38: a view could not be shared. MapLibre's hash (#zoom/lat/lng/bearing/pitch) writes it into the
    URL as the map moves, and a page opened with one shows that view instead of framing the data."""
    set_view(page, {"center": [2.35, 48.85], "zoom": 4.5})
    wait_for(page, lambda: page.execute_script("return window.location.hash").startswith("#4.5/48.85/2.35"),
             message="the view did not reach the URL")
    link = f"{server}/#6.25/48.1/11.2"
    page.get("about:blank")
    page.get(link)
    wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))
    zoom, lat, lng = page.execute_script(
        "const m = window.dggsMap, c = m.getCenter(); return [m.getZoom(), c.lat, c.lng]")
    assert (round(zoom, 2), round(lat, 2), round(lng, 2)) == (6.25, 48.1, 11.2)
    assert state(page)["lastError"] is None and state(page)["featureCount"] > 0
    page.get(f"{server}/")  # the module's page again, framed on the data, for the tests after this one
    wait_for(page, lambda: page.execute_script("return document.body.dataset.state") in ("idle", "error"))
    wait_for(page, lambda: page.execute_script("return window.dggsState.geography") != "loading")


def test_a_dataset_picker_shows_each_dataset_of_the_store(driver: Any, tmp_path: Path, data: dict[str, Any]) -> None:
    """Issue 38 item 5: a store holding points at level 9 (the default dataset) and a coarser dataset at level 5;
    the page lists both, shows the default one first and, once the other is picked, its own cells, levels and
    columns, fetched under its collection (map/cells?collection=, its zone information under /collections)."""
    from .serving import serving

    path = tmp_path / "two.db"
    lat, lng = data["lat"], data["lng"]
    africa = lat < 10  # the Africa cluster (and the clusters south of it) only
    with CellStore(path) as default, CellStore(path, dataset="coarse") as coarse:
        default.ingest_points(lat, lng, STORED_LEVEL, {"pop": data["pop"]})
        coarse.ingest_points(lat[africa], lng[africa], 5, {"rain": data["pop"][africa] * 0.5})
    with serving(path, "--max-features", str(MAX_FEATURES)) as base:
        driver.get(f"{base}/")
        wait_for(driver, lambda: driver.execute_script("return document.body.dataset.state") in ("idle", "error"))
        field = driver.find_element(By.ID, "collection-field")
        assert field.is_displayed()
        picker = Select(driver.find_element(By.ID, "collection"))
        assert [o.get_attribute("value") for o in picker.options] == ["two", "coarse"]
        assert picker.first_selected_option.get_attribute("value") == "two"
        assert state(driver)["collection"] is None and "at level 9" in driver.find_element(By.ID, "subtitle").text
        s = set_view(driver, GLOBE_VIEW)

        def drawn() -> list[str]:  # from ids by the WebGL layer, or as GeoJSON where the WebAssembly core is missing
            return sorted(driver.execute_script(
                "const ids = window.dggsDrawnZones ? window.dggsDrawnZones() : [];"
                "if (ids.length) return ids;"
                "const src = window.dggsMap.getSource('cells');"
                "return src ? src.serialize().data.features.map(f => f.properties.zone_id) : [];"))

        everywhere = {c[: s["level"] + 1] for c in dggs.latlng_to_cell(lat, lng, STORED_LEVEL)}
        assert set(drawn()) <= everywhere and drawn()
        s = choose(driver, "collection", "coarse")
        assert s["collection"] == "coarse" and s["level"] <= 5 and s["lastError"] is None
        assert driver.find_element(By.ID, "subtitle").text.startswith("coarse: ")
        assert "at level 5" in driver.find_element(By.ID, "subtitle").text
        columns = [o.get_attribute("value") for o in Select(driver.find_element(By.ID, "column")).options]
        assert columns == ["", "rain"]
        cells = {c[: s["level"] + 1] for c in dggs.latlng_to_cell(lat[africa], lng[africa], 5)}
        bbox = ",".join(str(x) for x in s["bbox"])
        doc = _get_json(f"{base}/map/cells?level={s['level']}&bbox={bbox}&stat=count&collection=coarse")
        assert drawn() == sorted(f["properties"]["zone_id"] for f in doc["features"]) and set(drawn()) <= cells
        urls = driver.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        assert any("/map/cells?" in u and "collection=coarse" in u for u in urls)
        s = choose(driver, "collection", "two")  # and back: the default dataset, under the root paths again
        assert s["collection"] is None and "at level 9" in driver.find_element(By.ID, "subtitle").text
        from dggs.server.vendor import STATIC_FOLDER

        core_missing = not (STATIC_FOLDER / "vendor" / "dggs").is_dir()  # no WebAssembly core built: GeoJSON then
        assert [e for e in js_errors(driver) if not (core_missing and "/static/vendor/dggs/" in e["message"])] == []
