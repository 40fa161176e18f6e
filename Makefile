# facesynth: `make demo` runs the whole pipeline on the built-in sample corpus,
# `make test` runs the test suite, `make lint` the linter and type checker, `make docs` the
# generated parts of docs/, `make report` rebuilds the report of docs/results.md.
# All create the environment with pip alone.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
FS     := $(BIN)/facesynth
STAMP  := $(VENV)/.installed
OUT    := out
CONFIG := configs/default.toml
PRESET ?= small
SEED   ?= 0

.PHONY: all demo test test-hostile lint docs report bench vendor blender-addon figures clean

all: demo

# pip installs without compiling to bytecode: Python writes a module's bytecode when it first
# imports it (its default), so only what runs is compiled (1 s of the first command) and not the
# whole environment (10 s of CPU). A PYTHONDONTWRITEBYTECODE set for the whole host would have each
# of the suite's processes compile what it imports anew, so the recipes run without it; facesynth
# itself is compiled here (0.3 s), for commands run outside make on such a host.
unexport PYTHONDONTWRITEBYTECODE

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet --quiet --no-compile -e '.[test]'
	$(BIN)/python -m compileall -q facesynth
	touch $@

# ruff and mypy (the lint extra), for `make lint` only.
LINT_STAMP := $(VENV)/.installed-lint

$(LINT_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet --quiet --no-compile -e '.[test,lint]'
	touch $@

# The suite on every core (pytest-xdist; TEST_WORKERS=0 runs it in one process).
TEST_WORKERS ?= auto

test: $(STAMP)
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS) --dist worksteal

# ruff's lint rules and mypy, as configured in pyproject.toml.
lint: $(LINT_STAMP)
	$(BIN)/ruff check facesynth tests benchmarks blender
	$(BIN)/mypy

# The generated parts of the docs: the stage table of docs/pipeline.md (facesynth/base/pipeline.py),
# the artifact reference of docs/file-format.md (facesynth/model/spec.py), the settings
# reference docs/configuration.md (facesynth/base/config.py) and the tables of the registered
# methods, export formats, capture formats and artifact kinds (facesynth/base/registry.py).
docs: $(STAMP)
	$(BIN)/python -m facesynth.base.pipeline docs/pipeline.md
	$(BIN)/python -m facesynth.model.spec docs/file-format.md
	$(BIN)/python -m facesynth.base.config > docs/configuration.md
	$(BIN)/python -m facesynth.base.registry docs/methods.md docs/exports.md docs/inputs.md docs/file-format.md

# The vendored three.js of the web player (facesynth/data/three.*), from npm: `npm ci` installs
# into node_modules/ the versions pinned in package.json and package-lock.json; terser (pinned there
# too, its options in package.json's `minify`) minifies three's core and module builds, as three
# ships no minified builds since r186; the orbit controls and the licence are copied as they are.
# tests/exports/test_three_vendor.py checks the files' sha256 and version. Needs Node.js and npm.
NPM ?= npm
THREE := node_modules/three

vendor:
	$(NPM) ci --ignore-scripts --no-audit --no-fund
	$(NPM) run --silent minify -- $(THREE)/build/three.core.js -o facesynth/data/three.core.js
	$(NPM) run --silent minify -- $(THREE)/build/three.module.js -o facesynth/data/three.module.js
	cp $(THREE)/examples/jsm/controls/OrbitControls.js facesynth/data/three.OrbitControls.js
	cp $(THREE)/LICENSE facesynth/data/three.LICENSE

# The long hostile-input run: every input kind x mutation over five seeds (several minutes;
# `make test` runs a quick part of it). `benchmarks/hostile.py` prints the same cases as a table.
test-hostile: $(STAMP)
	$(BIN)/python -m pytest -q -n $(TEST_WORKERS) -m hostile_long tests/hostile

# The report of docs/results.md (its seed-0 table is the README's), from fresh sample corpora
# over several seeds (mean and spread), with the host's processor and memory bandwidth
# -> docs/results.md (between its report markers), docs/results.json.
# Not part of `make test`: it runs the whole pipeline per seed (10 to 12 min for 3 seeds on 2 cores).
SEEDS            ?= 0 1 2
REPORT_PRESET    ?= paper
TUNE_EVALUATIONS ?= 12

report: $(STAMP)
	$(BIN)/python benchmarks/report.py --seeds $(SEEDS) --preset $(REPORT_PRESET) \
	    --tune-evaluations $(TUNE_EVALUATIONS) --work $(OUT)/report --out docs

# The figures of docs/inputs.md's video route (docs/images/video_actress_*.png): the virtual
# actress rendered, taken back through ingest, bind, normalize and solve --binding, and the rig
# beside the film at rest and mid-sentence (needs facesynth[video]; about a minute on 2 cores).
figures: $(STAMP)
	$(BIN)/python benchmarks/video_route_figures.py --work $(OUT)/figures --out docs/images

# The Blender add-on (docs/blender.md): blender/facesynth_blender zipped for Blender's
# Preferences > Add-ons > Install -> out/facesynth_blender.zip (Python's standard library only).
blender-addon:
	$(PYTHON) blender/make_zip.py $(OUT)

# --- the demo pipeline: each artifact depends on what it is made from (the stage table
# --- in docs/pipeline.md); a changed input or configuration reruns only what follows it.

$(OUT)/corpus/manifest.csv: $(STAMP)
	mkdir -p $(OUT)
	$(FS) sample-corpus $(OUT)/corpus --preset $(PRESET) --seed $(SEED) --overwrite

$(OUT)/corpus.h5: $(OUT)/corpus/manifest.csv $(CONFIG)
	$(FS) ingest $< -o $@ --overwrite

$(OUT)/normalized.h5: $(OUT)/corpus.h5 $(CONFIG)
	$(FS) normalize $< -o $@ --overwrite

$(OUT)/pca.h5: $(OUT)/normalized.h5 $(CONFIG)
	$(FS) pca $< -o $@ --overwrite

$(OUT)/db.h5: $(OUT)/pca.h5 $(CONFIG)
	$(FS) build-db $< -o $@ --overwrite

# Contaminated nodes out (paper V); synthesis searches the cleaned database.
$(OUT)/db_clean.h5: $(OUT)/db.h5 $(CONFIG)
	$(FS) prune $< --auto -o $@ --overwrite

$(OUT)/isomap.h5: $(OUT)/db_clean.h5 $(CONFIG)
	$(FS) isomap $< -o $@ --images $(OUT)/isomaps --overwrite

# Two held-out (test) sentences of the small corpus, each asked for in another emotion (the mouth
# opening with the phones and the voice: its loudness, the phones being given; synthesize.voice_given),
# solved onto the built-in rig and rendered
# beside openfacefx's lip sync of the same phones on the same rig and timing (left "facesynth",
# right "openfacefx").
DEMO_TAKES  := happy_s016 sad_s017
DEMO_LABELS := render.labels=["facesynth","openfacefx"]

$(OUT)/%.emotions.txt:
	mkdir -p $(OUT)
	echo "0 1000 $(firstword $(subst _, ,$*))" > $@

$(OUT)/%.motion.h5: $(OUT)/db_clean.h5 $(OUT)/%.emotions.txt $(CONFIG)
	$(FS) synthesize $< --phonemes $(OUT)/corpus/labels/$*.TextGrid --audio $(OUT)/corpus/audio/$*.wav \
	    --emotions $(OUT)/$*.emotions.txt -o $@ --overwrite

# The facial solve: the rig's blendshape weights per frame (rig curves); render poses the rig with them.
$(OUT)/%.curves.h5: $(OUT)/%.motion.h5 $(CONFIG)
	$(FS) solve $< -o $@ --overwrite

$(OUT)/%.openfacefx.h5: $(OUT)/%.motion.h5
	$(FS) openfacefx $< -o $@ --overwrite

$(OUT)/demo.avi: $(foreach t,$(DEMO_TAKES),$(OUT)/$(t).curves.h5 $(OUT)/$(t).openfacefx.h5) $(CONFIG)
	$(FS) render $(foreach t,$(DEMO_TAKES),$(OUT)/$(t).curves.h5) --view side-by-side \
	    $(foreach t,$(DEMO_TAKES),--compare $(OUT)/$(t).openfacefx.h5 --audio $(OUT)/corpus/audio/$(t).wav) \
	    --set '$(DEMO_LABELS)' -o $@ --overwrite

demo: $(OUT)/demo.avi $(OUT)/isomap.h5
	@echo "demo video: $(OUT)/demo.avi; phoneme-Isomaps: $(OUT)/isomaps/index.html"

.SECONDARY:

clean:
	rm -rf $(OUT)
