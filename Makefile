# Entry points. `make demo` and `make test` work on a fresh machine: both
# install the Debian packages (scripts/install-deps.sh) and build first.
.PHONY: deps build demo test test-unit test-python python test-asan fuzz bench clean

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

# The Python module (docs/python.md): built by `build`; prints how to import it.
python: build
	@echo "flexmb Python module: export PYTHONPATH=$(CURDIR)/$(BUILD)/python (then /usr/bin/python3 -c 'import flexmb')"

test-python: build
	ctest --preset release -j $(JOBS) -L python

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
