# The two commands of README.md:
#   make demo   install missing Debian packages, build everything, run the main job
#   make test   the same set-up, then the whole test suite (release + sanitizer pass)
BUILD      ?= build
BUILD_ASAN ?= build-asan
JOBS       ?= $(shell nproc)

.PHONY: all deps build build-asan addon demo test test-release test-asan bench fuzz clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > $(BUILD).configure.log || (cat $(BUILD).configure.log; exit 1)
	@cmake --build $(BUILD) -j $(JOBS)

build-asan: deps
	@cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOAK_SANITIZE=ON > $(BUILD_ASAN).configure.log || (cat $(BUILD_ASAN).configure.log; exit 1)
	@cmake --build $(BUILD_ASAN) -j $(JOBS)

# The Blender add-on, installable in Blender 3.x (bl_info) and 4.2+ (extension manifest).
addon:
	@mkdir -p $(BUILD) && /usr/bin/python3 blender_addon/build_zip.py $(BUILD)/soak_blender.zip
	@echo "built $(BUILD)/soak_blender.zip"

demo: build addon
	@$(BUILD)/bin/soak demo --out out/demo
	@bash povray/render_scenes.sh $(BUILD)/bin/soak out/demo/povray full
	@BLENDER_USER_SCRIPTS=$(CURDIR)/$(BUILD)/blender_user blender -b --factory-startup --python-exit-code 1 --python scenes/blender/render_all.py -- --addon $(BUILD)/soak_blender.zip --out out/demo/blender --soak $(BUILD)/bin/soak

# Each pass lists the skipped tests with their reasons and fails when a test
# failed, was skipped for want of povray or blender (the set-up installs
# them), or is registered without SKIP_RETURN_CODE 77 (scripts/test_skips.py).
CTEST_ARGS = --output-on-failure -j $(JOBS) --output-junit ctest-junit.xml \
  --test-output-size-passed 1000000 --test-output-size-failed 1000000

test-release: build
	@cd $(BUILD) && { ctest $(CTEST_ARGS); rc=$$?; \
	  /usr/bin/python3 $(CURDIR)/scripts/test_skips.py . ctest-junit.xml || rc=1; exit $$rc; }

# Sanitizer pass: every test but the long Monte Carlo ones (labelled slow).
test-asan: build-asan
	@cd $(BUILD_ASAN) && { ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest $(CTEST_ARGS) -LE slow; rc=$$?; \
	  /usr/bin/python3 $(CURDIR)/scripts/test_skips.py . ctest-junit.xml || rc=1; exit $$rc; }

test: test-release test-asan

# libFuzzer runs of tests/fuzz's targets (clang needed; not part of make test,
# which replays the stored corpora and reproducers in every build).
# FUZZ_SECONDS per target (default 900: an hour for the four).
BUILD_FUZZ   ?= build-fuzz
FUZZ_SECONDS ?= 900
fuzz: deps
	@CC=clang CXX=clang++ cmake -S . -B $(BUILD_FUZZ) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOAK_SANITIZE=ON -DSOAK_FUZZ=ON > $(BUILD_FUZZ).configure.log || (cat $(BUILD_FUZZ).configure.log; exit 1)
	@cmake --build $(BUILD_FUZZ) -j $(JOBS) --target fuzz_scene fuzz_preset fuzz_image fuzz_mesh
	@bash tests/fuzz/run.sh $(BUILD_FUZZ) $(FUZZ_SECONDS)

bench: build
	@bash c_core/bench/run.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD_FUZZ) $(BUILD).configure.log $(BUILD_ASAN).configure.log $(BUILD_FUZZ).configure.log
