# Convenience wrapper around scripts/install-deps.sh, CMake and CTest.
#   make run    install dependencies, build, solve the default problem (xml/default.xml)
#   make test   install dependencies, build, run the whole test suite, then `make sanitize`
#   make sanitize  the unit and small end-to-end tests under AddressSanitizer and
#               UndefinedBehaviorSanitizer, and 30 s of each fuzz target (Clang, $(BUILD)-sanitize)
#   make doc    the API reference of the public headers (build/doc/api/html)
BUILD ?= build
SANITIZE_BUILD ?= $(BUILD)-sanitize
JOBS ?= 2
NP ?= 2
INPUT ?= xml/default.xml
OUTPUT ?= results/default

# Open MPI: allow root (CI runs as root), allow more ranks than cores, and avoid the
# single-copy shared-memory path that needs ptrace rights containers often lack.
export OMPI_ALLOW_RUN_AS_ROOT = 1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM = 1
export OMPI_MCA_rmaps_base_oversubscribe = 1
export OMPI_MCA_btl_vader_single_copy_mechanism = none

.PHONY: all deps configure build run test sanitize doc clean

all: build

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# The Python module: Debian's python3 finds it in $(BUILD)/python through a .pth file in
# the user's site-packages (no root needed; `cmake --install` puts it in the prefix instead).
build: configure
	cmake --build $(BUILD) -j $(JOBS)
	/usr/bin/python3 scripts/python_path.py $(BUILD)/python

run: build
	mpirun -np $(NP) $(BUILD)/bin/signorini $(INPUT) --output $(OUTPUT)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	$(MAKE) sanitize

sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
	      -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
	      -DSIGNORINI_SANITIZE=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target sanitize_checks
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -L sanitize

doc: build
	cmake --build $(BUILD) --target doc

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD)
