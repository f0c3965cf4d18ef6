# Entry points. `make demo` and `make test` work on a fresh machine: both
# install the Debian packages (scripts/install-deps.sh) and build first.
.PHONY: deps build demo test test-unit test-asan fuzz bench clean

JOBS ?= $(shell nproc)
BUILD := build/release
DEMO_OUT ?= out/demo
FUZZ_SECONDS ?= 20

deps:
	bash scripts/install-deps.sh

build: deps
	cmake --preset release >/dev/null
	cmake --build --preset release -j $(JOBS)

demo: build
	bash scripts/demo.sh $(DEMO_OUT)

test: build
	ctest --preset release -j $(JOBS)

test-unit: build
	ctest --preset release -j $(JOBS) -L unit

test-asan: deps
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS) --target flexmb_unit_tests
	ctest --preset asan -j $(JOBS)

fuzz: deps
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS) --target flexmb_fuzz_targets
	bash scripts/run-fuzz.sh build/asan/bin $(FUZZ_SECONDS)

bench: build
	cmake --build --preset release -j $(JOBS) --target bench/all
	$(BUILD)/bin/flexmb_bench

clean:
	rm -rf build out
