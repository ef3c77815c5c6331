# Set-up and checks. `make demo` and `make test` install whatever is missing
# (Debian packages when run as root, a venv, the package with its extension).

VENV      ?= .venv
PYTHON    ?= python3
PY        := $(VENV)/bin/python
STAMP     := $(VENV)/.g2s-installed
DEMO_OUT  ?= g2s-demo
WHEEL_DIR ?= dist
DEB_PACKAGES := librecast-dev cmake g++ make
# chromium: the headless browser tests/test_html_report.py drives (make test only)
TEST_DEB_PACKAGES := chromium
README_IMAGE := docs/images/demo-heatmap.png
REGIONS_IMAGE := docs/images/regions-dungeon.png
# the Khronos glTF validator tests/test_gltf.py runs (make test only), from npm into the venv
GLTF_VALIDATOR := $(VENV)/node/node_modules/gltf-validator
GLTF_VALIDATOR_VERSION := 2.0.0-dev.3.10
# three.js, which draws the GLB for docs/images/glb-threejs.png (make docs-images only)
THREE_VERSION := 0.187.0

.PHONY: demo test setup system-deps benchmark clean readme-image regions-image docs-images wheel fuzz

demo: setup
	$(VENV)/bin/g2s demo -o $(DEMO_OUT) --force

test: DEB_PACKAGES += $(TEST_DEB_PACKAGES)
test: setup $(GLTF_VALIDATOR)
	$(PY) -m pytest -q -n 2

$(GLTF_VALIDATOR): | setup
	@if command -v npm >/dev/null 2>&1; then \
	  npm install --no-save --no-package-lock --no-audit --no-fund --prefix $(VENV)/node \
	    gltf-validator@$(GLTF_VALIDATOR_VERSION); \
	elif [ "$$(id -u)" = 0 ]; then \
	  echo "installing Debian packages: nodejs npm"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq nodejs npm >/dev/null && \
	  npm install --no-save --no-package-lock --no-audit --no-fund --prefix $(VENV)/node \
	    gltf-validator@$(GLTF_VALIDATOR_VERSION); \
	else \
	  echo "npm is missing, so the glTF validator test will be skipped; install it with: sudo apt-get install nodejs npm"; \
	fi

# The README's picture: the demo's top-down heat map.
readme-image: setup
	$(VENV)/bin/g2s demo -o $(DEMO_OUT) --force --format png --quiet
	mkdir -p $(dir $(README_IMAGE))
	cp $(DEMO_OUT)/heatmap.png $(README_IMAGE)

# docs/plugins.md's picture: regions and chokepoints of the default dungeon sample.
regions-image: setup
	$(VENV)/bin/g2s run configs/level_regions.yaml sample:dungeon -o $(DEMO_OUT)-regions --force --format png --quiet
	mkdir -p $(dir $(REGIONS_IMAGE))
	cp $(DEMO_OUT)-regions/heatmap.png $(REGIONS_IMAGE)

# A self-contained wheel in dist/: built from this checkout, then repaired by
# auditwheel, which copies libRecast/libDetour into it (graph2structure.libs/)
# and tags it manylinux for the oldest glibc the binaries allow.
wheel: setup
	rm -rf build/wheel-raw
	$(PY) -m pip wheel --no-deps --no-build-isolation -q -w build/wheel-raw .
	PATH="$(abspath $(VENV))/bin:$$PATH" $(PY) -m auditwheel repair -w $(WHEEL_DIR) build/wheel-raw/graph2structure-*.whl

# docs/outputs.md's pictures: the demo's report and GLB (three.js) in headless chromium.
docs-images: setup
	$(VENV)/bin/g2s demo -o $(DEMO_OUT) --force --quiet
	npm install --no-save --no-package-lock --no-audit --no-fund --prefix $(VENV)/node \
	  gltf-validator@$(GLTF_VALIDATOR_VERSION) three@$(THREE_VERSION)
	$(PY) tools/screenshots.py $(DEMO_OUT) $(VENV)/node/node_modules docs/images

benchmark: setup
	$(PY) benchmarks/pipeline.py

# Fuzz the mesh, config and points loaders for FUZZ_MINUTES (crashing inputs go to tests/fuzz/crashes/).
FUZZ_MINUTES ?= 10
fuzz: setup
	$(PY) -m tests.fuzz.fuzz_loaders --minutes $(FUZZ_MINUTES)

setup: $(STAMP)

system-deps:
	@missing=""; \
	for pkg in $(DEB_PACKAGES); do dpkg -s $$pkg >/dev/null 2>&1 || missing="$$missing $$pkg"; done; \
	$(PYTHON) -c "import venv, ensurepip" >/dev/null 2>&1 || missing="$$missing python3-venv"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "installing Debian packages:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else \
	    echo "g2s needs the Debian packages:$$missing"; \
	    echo "install them with: sudo apt-get install$$missing"; \
	    exit 1; \
	  fi; \
	fi

$(STAMP): pyproject.toml CMakeLists.txt $(wildcard src/*) | system-deps
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q scikit-build-core nanobind
	@# a venv made before the rename still holds the distribution "g2s", whose entry points would register twice
	$(PY) -m pip uninstall -y -q g2s 2>/dev/null || true
	$(PY) -m pip install -q --no-build-isolation -e '.[dev,batch]'
	touch $@

clean:
	rm -rf build dist $(DEMO_OUT) $(DEMO_OUT)-regions
