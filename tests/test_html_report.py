"""report.html in headless Chromium, offline: no console errors, no network, the plot drawn with all its layers,
the default view showing what matters and the whole level, above the fold; and a level far from the origin drawn in
its local frame, read in world metres."""

from __future__ import annotations

import base64
import gzip
import io
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import g2s_core
from g2s_core.mesh import generate_level
from g2s_plugins.outputs import colours, html_report
from tests.conftest import PROJECT
from tests.test_far_from_origin import moved
from tests.test_outputs import make_result

CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    # WebGL for plotly's 3D scene, in software
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
]

needs_chromium = pytest.mark.skipif(not CHROMIUM.exists(), reason="Debian's chromium is not installed (/usr/bin/chromium); "
                                    "`make test` installs it when run as root, or: sudo apt-get install chromium")


def _depth_classes(tree) -> int:
    return len({(tree.nodes[v]["depth"] - 1) % len(colours.DEPTH_COLOURS) for _, v in tree.edges})


def test_report_is_self_contained(tmp_path):
    result = make_result()
    path, = html_report.write(result, tmp_path)
    text = path.read_text(encoding="utf-8")
    packed = re.findall(r'<script id="g2s-plotly" type="application/gzip;base64">([^<]+)</script>', text)
    assert len(packed) == 1 and gzip.decompress(base64.b64decode(packed[0])).decode().count("plotly.js v") == 1
    assert text.count("plotly.js v") == 0  # the library, embedded once, compressed
    assert not re.search(r"<(script|link|img)[^>]+(src|href)=", text)  # nothing loaded from elsewhere
    assert "terminals &lt;b&gt;near&lt;/b&gt; the edge &amp; one more" in text  # warnings escaped
    assert "evaluation (" not in text
    result.metrics["traffic"] = {"area_within_6m": 0.97413, "rho": 0.8252}
    assert "<dt>evaluation (traffic)</dt><dd>area_within_6m 0.9741, rho 0.8252</dd>" in html_report.render(result)


FOLD = {"width": 1400, "height": 1000}
"""The window the report must fit without scrolling to see the plot."""


@needs_chromium
def test_report_renders_offline_in_chromium(tmp_path):
    sync_api = pytest.importorskip("playwright.sync_api")
    result = make_result()
    result.formats = ("json", "html", "glb")
    path, = html_report.write(result, tmp_path)
    forest_lines, structure_lines = _depth_classes(result.forest), _depth_classes(result.structure)
    expected_traces = (1            # level mesh
                       + 2          # step 1: edges, nodes
                       + 2          # step 2: terminals, openings
                       + 2          # step 3: edges, nodes
                       + forest_lines + 1      # step 4: edges by depth, nodes
                       + structure_lines + 1   # step 5
                       + 1          # roots
                       + 2 * 2)     # two analysis keys: edges, nodes
    layers = ["Level mesh", "Step 1: initial graph", "Step 2: terminals", "Step 3: Steiner tree",
              "Step 4: rooted trees", "Step 5: simplified structure", "Roots", "Analysis: betweenness",
              "Analysis: degree"]

    problems: list[str] = []
    outside: list[str] = []
    with sync_api.sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        try:
            context = browser.new_context(offline=True, viewport=FOLD)
            page = context.new_page()
            page.on("console", lambda m: problems.append(f"console {m.type}: {m.text}") if m.type == "error" else None)
            page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
            page.on("requestfailed", lambda r: problems.append(f"request failed: {r.url}"))
            page.on("request", lambda r: outside.append(r.url) if not r.url.startswith(("file://", "blob:")) else None)
            page.goto(path.as_uri(), wait_until="load")
            page.wait_for_function("() => { const p = document.querySelector('.js-plotly-plot');"
                                   " return p && p._fullLayout && p.querySelector('.gl-container canvas'); }",
                                   timeout=60_000)
            plot = ".js-plotly-plot"
            assert page.evaluate(f"document.querySelector('{plot}').data.length") == expected_traces
            assert page.evaluate("Array.from(document.querySelectorAll('.legendtext')).map(e => e.textContent)") == layers
            webgl = page.evaluate("(() => { const c = document.querySelector('.gl-container canvas');"
                                  " return !!(c.getContext('webgl') || c.getContext('webgl2')); })()")
            assert webgl, "the 3D scene has no WebGL context"
            _check_default_view(page, result)
            # a click on a legend entry shows the whole layer
            page.locator(".legend .traces", has_text="Step 1: initial graph").locator(".legendtoggle").click(timeout=5_000)
            page.wait_for_function(f"document.querySelector('{plot}').data.filter("
                                   "t => t.name === 'Step 1: initial graph').every(t => t.visible === true)",
                                   timeout=10_000)
            rows = page.evaluate("Array.from(document.querySelectorAll('#stages tbody tr'))"
                                 ".map(r => Array.from(r.cells).map(c => c.textContent))")
            assert [r[0] for r in rows] == ["Step 1", "Step 2", "Step 3", "Step 4", "Step 5", "Post-process", "total"]
            assert rows[0][3:] == [str(result.graph.number_of_nodes()), str(result.graph.number_of_edges())]
            assert rows[1][3] == "5"  # terminals
            config = page.inner_text("#config")
            assert "plugin: surface_los" in config
            assert "formats:\n  - json\n  - html\n  - glb" in config  # what was written, not the config's default
            assert page.inner_text("#warnings") == "terminals <b>near</b> the edge & one more"
            _check_whole_level_in_view(page)  # last: it hides the other layers
        finally:
            browser.close()
    assert not problems, problems
    assert not outside, outside


def _check_default_view(page, result) -> None:
    """Level, structure (coloured by the first value), roots, terminals and openings are shown at first, above the fold."""
    visible = page.evaluate("document.querySelector('.js-plotly-plot').data.map(t => [t.name, t.visible, t.mode || ''])")
    shown = {(name, mode) for name, state, mode in visible if state is True}
    assert shown == {("Level mesh", ""), ("Step 2: terminals", "markers"), ("Step 2: terminals", "lines"),
                     ("Roots", "markers"), ("Analysis: betweenness", "lines"), ("Analysis: betweenness", "markers")}
    # every structure edge is drawn in the shown layer: two points and a gap each
    drawn = page.evaluate("(() => { const t = document.querySelector('.js-plotly-plot')._fullData.find("
                          "t => t.name === 'Analysis: betweenness' && t.mode === 'lines');"
                          " return Array.from(t.x).filter(v => Number.isFinite(v)).length; })()")
    assert drawn == 2 * result.structure.number_of_edges()
    roots = page.evaluate("document.querySelector('.js-plotly-plot')._fullData.find(t => t.name === 'Roots').x.length")
    assert roots == len(result.structure.graph["roots"])
    rect = page.evaluate("document.getElementById('g2s-plot').getBoundingClientRect().toJSON()")
    assert rect["top"] >= 0 and rect["bottom"] <= FOLD["height"], rect  # the whole plot without scrolling
    assert rect["height"] >= 0.6 * FOLD["height"], rect


def _check_whole_level_in_view(page) -> None:
    """Only the level mesh, opaque, no axes: its pixels stay clear of the plot's edges (nothing clipped)."""
    page.evaluate("""(async () => {
        const p = document.querySelector('.js-plotly-plot');
        const level = p.data.map((t, i) => t.name === 'Level mesh' ? i : -1).filter(i => i >= 0);
        await Plotly.restyle(p, {visible: false}, p.data.map((t, i) => i).filter(i => !level.includes(i)));
        await Plotly.restyle(p, {opacity: 1, color: 'rgb(0,0,0)'}, level);
        await Plotly.relayout(p, {showlegend: false, 'scene.xaxis.visible': false,
                                  'scene.yaxis.visible': false, 'scene.zaxis.visible': false});
    })()""")
    page.wait_for_timeout(500)
    from PIL import Image

    canvas = page.locator(".gl-container canvas").first
    image = np.asarray(Image.open(io.BytesIO(canvas.screenshot())).convert("L"))
    rows, columns = np.nonzero(image < 128)
    assert len(rows) > 0.05 * image.size, "the level is not drawn"
    height, width = image.shape
    margins = (rows.min(), height - 1 - rows.max(), columns.min(), width - 1 - columns.max())
    assert min(margins) > 2, f"the level touches the plot's edge (margins top, bottom, left, right: {margins})"


def test_nav_test_report_is_small(shared_data, tmp_path):
    """The real level's report (plotly.js and the geometry inside) stays under 3 MB."""
    out = tmp_path / "out"
    command = [sys.executable, "-m", "g2s_core.cli", "run", str(PROJECT / "configs" / "map_analysis.yaml"),
               str(shared_data / "nav_test.obj"), "-o", str(out), "--format", "html", "--quiet"]
    done = subprocess.run(command, capture_output=True, text=True, cwd=PROJECT)
    assert done.returncode == 0, done.stderr
    size = (out / "report.html").stat().st_size
    assert size < 3_000_000, f"report.html is {size / 1e6:.2f} MB"


def test_hover_gives_role_position_in_metres_and_each_value_once():
    result = make_result()
    root = result.structure.graph["roots"][0]
    text = html_report.hover_text(result.structure, root, result, {root})
    x, y, z = result.structure.nodes[root]["pos"]
    lines = text.split("<br>")
    assert lines[0] == f"node {root} (root, terminal)"
    assert lines[1] == f"x {x:.2f} m, y {y:.2f} m, z {z:.2f} m"
    assert [line.split(":")[0] for line in lines[3:]] == ["betweenness", "degree"]


def _coordinates(trace: dict) -> np.ndarray:
    """(n, 3) a trace's x, y, z as the page holds them: plotly's typed arrays (dtype and base64 bytes)."""
    assert all(trace[axis]["dtype"] == "f4" for axis in "xyz")
    return np.stack([np.frombuffer(base64.b64decode(trace[axis]["bdata"]), dtype=np.float32) for axis in "xyz"], axis=1)


HOVER_POSITION = re.compile(r"x (-?\d+\.\d\d) m, y (-?\d+\.\d\d) m, z (-?\d+\.\d\d) m")


def _hover_positions(trace: dict) -> np.ndarray:
    return np.array([[float(v) for v in HOVER_POSITION.search(text).groups()] for text in trace.get("text") or ()])


def test_a_level_far_from_the_origin_is_drawn_in_its_local_frame_and_read_in_world_metres():
    # 1,000 km out, float32 world coordinates would step by 6 cm; the view holds them less the local origin
    level = generate_level("sample:loop_of_four_rooms")
    shift = np.array([1e6, 0.0, -1e6])
    near, far = (json.loads(html_report.build_figure(g2s_core.run(moved(level, s), "level_regions")).to_json())
                 for s in (0 * shift, shift))
    assert [(t["type"], t.get("name")) for t in far["data"]] == [(t["type"], t.get("name")) for t in near["data"]]
    hovered = 0
    for at_origin, out in zip(near["data"], far["data"]):
        local, reference = _coordinates(out), _coordinates(at_origin)
        # the far run's world positions less the move agree with the origin's within 2e-9 m: within a float32 step
        step = np.spacing(np.float32(max(np.nanmax(np.abs(reference), initial=0.0), 1.0)))
        assert np.array_equal(np.isnan(local), np.isnan(reference))
        assert np.nanmax(np.abs(local - reference), initial=0.0) <= step
        world, origin_world = _hover_positions(out), _hover_positions(at_origin)
        assert world.shape == origin_world.shape
        if len(world):  # every hover of a position shows it in world metres, to the centimetre
            assert np.abs(world - shift - origin_world).max() <= 0.0100001
            hovered += len(world)
    assert hovered > 0
    scene, reference = far["layout"]["scene"], near["layout"]["scene"]
    assert [scene[f"{a}axis"]["title"]["text"] for a in "xyz"] == ["X − 1,000,000 (m)", "Y (m, up)", "Z + 1,000,000 (m)"]
    assert [reference[f"{a}axis"]["title"]["text"] for a in "xyz"] == ["X (m)", "Y (m, up)", "Z (m)"]
    for axis in ("xaxis", "yaxis", "zaxis"):
        assert scene[axis]["range"] == pytest.approx(reference[axis]["range"], abs=1e-6)


def test_stage_hint_says_step_2_counts_terminals_and_waypoints():
    """Step 2's #N counts terminals and waypoints (a cover's 32 and 107 on nav_test: 139), not terminals alone."""
    text = html_report.render(make_result())
    assert "#N is, for step 2, the number of nodes the Steiner tree joins (the terminals and any waypoints)" in text
    assert "<dt>terminals</dt><dd>5</dd>" in text  # no waypoints, nothing added


def test_colour_bar_of_whole_numbers_ticks_whole_numbers():
    """The report's degree bar (whole numbers) ticks 0, 1, 2 ...; betweenness (real) keeps plotly's own ticks."""
    figure = html_report.build_figure(make_result())
    bars = {trace.name: trace.marker.colorbar for trace in figure.data
            if getattr(trace, "mode", "") == "markers" and trace.name.startswith("Analysis: ")}
    degree = bars[html_report.LAYER_ANALYSIS.format(key="degree")]
    assert (degree.tickmode, degree.tick0, degree.dtick) == ("linear", 0, 1)
    assert bars[html_report.LAYER_ANALYSIS.format(key="betweenness")].dtick is None
