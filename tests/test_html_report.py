"""report.html in headless Chromium, offline: no console errors, no network, the plot drawn with all its layers."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from g2s_plugins.outputs import colours, html_report
from tests.test_outputs import make_result

CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    # WebGL for plotly's 3D scene, in software
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
]

pytestmark = pytest.mark.skipif(not CHROMIUM.exists(), reason="Debian's chromium is not installed (/usr/bin/chromium); "
                                "`make test` installs it when run as root, or: sudo apt-get install chromium")


def _depth_classes(tree) -> int:
    return len({(tree.nodes[v]["depth"] - 1) % len(colours.DEPTH_COLOURS) for _, v in tree.edges})


def test_report_is_self_contained(tmp_path):
    result = make_result()
    path, = html_report.write(result, tmp_path)
    text = path.read_text(encoding="utf-8")
    assert text.count("plotly.js v") == 1  # the library, embedded once
    assert not re.search(r"<(script|link|img)[^>]+(src|href)=", text)  # nothing loaded from elsewhere
    assert "terminals &lt;b&gt;near&lt;/b&gt; the edge &amp; one more" in text  # warnings escaped


def test_report_renders_offline_in_chromium(tmp_path):
    sync_api = pytest.importorskip("playwright.sync_api")
    result = make_result()
    path, = html_report.write(result, tmp_path)
    forest_lines, structure_lines = _depth_classes(result.forest), _depth_classes(result.structure)
    expected_traces = (1            # level mesh
                       + 2          # step 1: edges, nodes
                       + 2          # step 2: terminals, openings
                       + 2          # step 3: edges, nodes
                       + forest_lines + 2      # step 4: edges by depth, nodes, roots
                       + structure_lines + 2   # step 5
                       + 2 * 2)     # two analysis keys: edges, nodes
    layers = ["Level mesh", "Step 1: initial graph", "Step 2: terminals", "Step 3: Steiner tree",
              "Step 4: rooted trees", "Step 5: simplified structure", "Analysis: betweenness", "Analysis: degree"]

    problems: list[str] = []
    outside: list[str] = []
    with sync_api.sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        try:
            context = browser.new_context(offline=True)
            page = context.new_page()
            page.on("console", lambda m: problems.append(f"console {m.type}: {m.text}") if m.type == "error" else None)
            page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
            page.on("requestfailed", lambda r: problems.append(f"request failed: {r.url}"))
            page.on("request", lambda r: outside.append(r.url) if not r.url.startswith("file://") else None)
            page.goto(path.as_uri(), wait_until="load")
            page.wait_for_function("() => { const p = document.querySelector('.js-plotly-plot');"
                                   " return p && p._fullLayout && p.querySelector('.gl-container canvas'); }",
                                   timeout=30_000)
            plot = ".js-plotly-plot"
            assert page.evaluate(f"document.querySelector('{plot}').data.length") == expected_traces
            assert page.evaluate("Array.from(document.querySelectorAll('.legendtext')).map(e => e.textContent)") == layers
            webgl = page.evaluate("(() => { const c = document.querySelector('.gl-container canvas');"
                                  " return !!(c.getContext('webgl') || c.getContext('webgl2')); })()")
            assert webgl, "the 3D scene has no WebGL context"
            visible = page.evaluate(f"document.querySelector('{plot}').data.map(t => [t.name, t.visible])")
            shown = {name for name, state in visible if state is True}
            assert shown == {"Level mesh", "Analysis: betweenness"}
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
            assert "plugin: surface_los" in page.inner_text("#config")
            assert page.inner_text("#warnings") == "terminals <b>near</b> the edge & one more"
        finally:
            browser.close()
    assert not problems, problems
    assert not outside, outside
