# Entry points. `make demo` and `make test` work on a fresh machine: both
# install the Debian packages (scripts/install-deps.sh) and build first.
.PHONY: deps build build-asan demo test test-unit test-python python test-asan fuzz bench clean

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

# Every test: the validation and Python tests in the release build, the
# unit tests in the sanitizer build (clang, ASan + UBSan; docs/design.md,
# "Where the tests run").
test: build build-asan
	ctest --preset release -j $(JOBS)
	ctest --preset asan -j $(JOBS)

test-unit: build-asan
	ctest --preset asan -j $(JOBS)

# The Python module (docs/python.md): built by `build`; prints how to import it.
python: build
	@echo "flexmb Python module: export PYTHONPATH=$(CURDIR)/$(BUILD)/python (then /usr/bin/python3 -c 'import flexmb')"

test-python: build
	ctest --preset release -j $(JOBS) -L python

build-asan: deps
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS) --target flexmb_unit_tests

test-asan: test-unit

fuzz: deps
	cmake --preset asan >/dev/null
	cmake --build --preset asan -j $(JOBS) --target flexmb_fuzz_targets
	bash scripts/run-fuzz.sh build/asan/bin $(FUZZ_SECONDS)

bench: build
	cmake --build --preset release -j $(JOBS) --target bench/all
	$(BUILD)/bin/flexmb_bench

clean:
	rm -rf build out
