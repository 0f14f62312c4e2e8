# The two commands of README.md:
#   make demo   install missing Debian packages, build everything, run the main job
#   make test   the same set-up, then the whole test suite (release + sanitizer pass)
BUILD      ?= build
BUILD_ASAN ?= build-asan
JOBS       ?= $(shell nproc)

.PHONY: all deps build build-asan addon demo test test-release test-asan bench clean

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
	@BLENDER_USER_SCRIPTS=$(CURDIR)/$(BUILD)/blender_user blender -b --factory-startup --python-exit-code 1 --python scenes/blender/render_all.py -- --addon $(BUILD)/soak_blender.zip --out out/demo/blender --soak $(BUILD)/bin/soak

test-release: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Sanitizer pass: every test but the long Monte Carlo ones (labelled slow).
test-asan: build-asan
	@cd $(BUILD_ASAN) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) -LE slow

test: test-release test-asan

bench: build
	@bash c_core/bench/run.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD).configure.log $(BUILD_ASAN).configure.log
