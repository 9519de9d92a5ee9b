# iblkit: one entry point for people and CI.
#   make demo    install, fetch assets, build, run the pipeline on the bundled scenes
#   make test    install, fetch assets, build, run every test (ctest)
#   make build   configure and build into build/ (programs, tests, benchmarks)
#   make programs  only the programs (what make demo needs)
#   make bench   build and run the benchmarks (results: docs/benchmarks.md)
#   make sanitize  build with ASan+UBSan into build-asan/ and run the tests there
#   make fuzz    build the libFuzzer targets (clang) into build-fuzz/ and run each for FUZZ_SECONDS
#                (docs/robustness.md); make test runs them for TEST_FUZZ_SECONDS each (0: not at all)
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
TEST_FUZZ_SECONDS ?= 10

.PHONY: all setup assets configure build programs test demo bench sanitize fuzz fuzz-build clean

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
	@if [ "$(TEST_FUZZ_SECONDS)" != 0 ]; then $(MAKE) --no-print-directory fuzz FUZZ_SECONDS=$(TEST_FUZZ_SECONDS); fi

programs: configure
	@cmake --build $(BUILD) -j $(JOBS) --target iblkit_programs

demo: programs assets
	@bash scripts/demo.sh $(BUILD)

bench: build assets
	@bash scripts/bench.sh $(BUILD)

sanitize:
	@$(MAKE) --no-print-directory test BUILD=build-asan TEST_FUZZ_SECONDS=0 CMAKE_FLAGS="-DIBLKIT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIBLKIT_BUILD_BENCHMARKS=OFF"

# Only core, bakefile, reference/pass_sum and fuzz/, with clang's -fsanitize=fuzzer,address,undefined (CMakeLists.txt).
fuzz-build: setup
	@cmake -S . -B $(FUZZ_BUILD) -G Ninja -DIBLKIT_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target iblkit_fuzz_targets

fuzz: fuzz-build assets
	@bash scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

clean:
	rm -rf build build-asan build-fuzz out
