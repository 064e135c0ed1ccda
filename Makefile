# geardyn's two commands (README): `make demo` and `make test`. Both set up what is missing
# (Debian packages, configure, build) first, so they work on a fresh clone.
BUILD_DIR ?= build
CTEST_JOBS ?= $(shell nproc)

.PHONY: all setup demo test test-long sanitize fuzz bench format clean

all: setup

setup:
	bash scripts/setup.sh

# The demo needs the CLI and the Python module only; the tests' binaries are built by `make test`.
demo:
	BUILD_TARGETS=geardyn_demo_programs bash scripts/setup.sh
	bash scripts/demo.sh

# The default suite: unit + validation + examples + CLI + Python (everything but label `long`).
test: setup
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(CTEST_JOBS) -LE long

test-long: setup
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(CTEST_JOBS) -L long

sanitize:
	bash scripts/sanitize.sh

fuzz:
	bash scripts/fuzz.sh

# Through setup.sh: the same packages, ccache and pinned interpreter as the main build.
bench:
	BUILD_DIR=build-bench GEARDYN_CMAKE_ARGS="-DGEARDYN_BUILD_BENCHMARKS=ON \
	  -DGEARDYN_BUILD_TESTS=OFF -DGEARDYN_BUILD_PYTHON=OFF" bash scripts/setup.sh
	build-bench/bin/geardyn_bench

format:
	git ls-files '*.h' '*.cpp' '*.h.in' | grep -v '\.in$$' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) build-asan build-fuzz build-bench results
