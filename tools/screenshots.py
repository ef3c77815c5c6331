"""The pictures of docs/outputs.md: the demo's report.html and structure.glb, as a reader's browser shows them.

Both are taken in headless Chromium (Debian's, through playwright): the
report as it opens in a 1400 x 1000 window, the GLB drawn by three.js's
glTF loader (npm package ``three``, installed by ``make docs-images``) under
a plain sky light, seen from above one corner, close enough that the
structure's tubes and markers show (the level's far ends leave the frame). Files are served to the page
by playwright from disk; nothing is fetched from the network.

Usage: python tools/screenshots.py DEMO_FOLDER NODE_MODULES IMAGE_FOLDER
"""

from __future__ import annotations

import io
import mimetypes
import sys
from pathlib import Path

from PIL import Image
from playwright.sync_api import Route, sync_playwright

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]
WINDOW = {"width": 1400, "height": 1000}
WIDTH = 1000
"""Width of the committed pictures, pixels."""
COLOURS = 256
"""Palette size of the committed pictures (keeps them small)."""
ORIGIN = "http://g2s.invalid"

VIEWER = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><style>html, body { margin: 0; background: #fff; }</style>
<script type="importmap">{"imports": {"three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/"}}</script>
</head><body>
<script type="module">
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(innerWidth, innerHeight);
renderer.setClearColor(0xffffff);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.5);
sun.position.set(0.4, 1.0, 0.3);
scene.add(sun);
new GLTFLoader().load("/structure.glb", (gltf) => {
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const centre = box.getCenter(new THREE.Vector3());
  const radius = box.getBoundingSphere(new THREE.Sphere()).radius;
  const camera = new THREE.PerspectiveCamera(40, innerWidth / innerHeight, radius / 100, radius * 10);
  const direction = new THREE.Vector3(1.0, 1.5, 1.2).normalize();
  camera.position.copy(centre).addScaledVector(direction, 0.5 * radius / Math.sin(THREE.MathUtils.degToRad(20)));
  camera.lookAt(centre);
  renderer.render(scene, camera);
  window.groups = gltf.scene.children.map((c) => c.name);
  window.rendered = true;
});
</script></body></html>"""


def shrink(png: bytes, path: Path) -> None:
    image = Image.open(io.BytesIO(png)).convert("RGB")
    image = image.resize((WIDTH, round(image.height * WIDTH / image.width)), Image.LANCZOS)
    image.quantize(COLOURS, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(path, optimize=True)
    print(f"wrote {path} ({path.stat().st_size // 1024} KB)")


def serve(files: dict[str, Path | str]):
    def handle(route: Route) -> None:
        name = route.request.url[len(ORIGIN):]
        source = files.get(name)
        if source is None and name.startswith("/three/"):
            source = files["/three/"] / name[len("/three/"):]  # type: ignore[operator]
        if isinstance(source, str):
            route.fulfill(body=source, content_type="text/html")
        elif source is not None and source.is_file():
            route.fulfill(path=str(source), content_type=mimetypes.guess_type(name)[0] or "application/octet-stream")
        else:
            route.fulfill(status=404)
    return handle


def main(demo: Path, modules: Path, images: Path) -> None:
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        page = browser.new_page(viewport=WINDOW)
        page.goto((demo / "report.html").resolve().as_uri())
        page.wait_for_function("() => { const p = document.querySelector('.js-plotly-plot');"
                               " return p && p._fullLayout && p.querySelector('.gl-container canvas'); }",
                               timeout=120_000)
        page.wait_for_timeout(1000)
        shrink(page.screenshot(), images / "report.png")

        page = browser.new_page(viewport={"width": 1400, "height": 900})
        page.route(f"{ORIGIN}/**", serve({"/": VIEWER, "/structure.glb": demo / "structure.glb",
                                          "/three/": modules / "three"}))
        page.goto(f"{ORIGIN}/")
        page.wait_for_function("() => window.rendered === true", timeout=120_000)
        print("glTF groups:", page.evaluate("window.groups"))
        shrink(page.screenshot(), images / "glb-threejs.png")
        browser.close()


if __name__ == "__main__":
    main(Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3]))
