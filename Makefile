# iblkit: one entry point for people and CI.
#   make demo    install, fetch assets, build, run the pipeline on the bundled scenes
#   make test    install, fetch assets, build, run every test (ctest)
#   make build   configure and build into build/ (programs, tests, benchmarks)
#   make programs  only the programs (what make demo needs)
#   make bench   build and run the benchmarks (results: docs/benchmarks.md)
#   make sanitize  build with ASan+UBSan into build-asan/ and run the tests there
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all setup assets configure build programs test demo bench sanitize clean

all: build

setup:
	@bash scripts/setup.sh

assets: setup
	@bash assets/fetch.sh

configure: setup
	@cmake -S . -B $(BUILD) -G Ninja $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build assets
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

programs: configure
	@cmake --build $(BUILD) -j $(JOBS) --target iblkit_programs

demo: programs assets
	@bash scripts/demo.sh $(BUILD)

bench: build assets
	@bash scripts/bench.sh $(BUILD)

sanitize:
	@$(MAKE) --no-print-directory test BUILD=build-asan CMAKE_FLAGS="-DIBLKIT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIBLKIT_BUILD_BENCHMARKS=OFF"

clean:
	rm -rf build build-asan out
