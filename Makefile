# Convenience wrapper around scripts/install-deps.sh, CMake and CTest.
#   make run    install dependencies, build, solve the default problem (xml/default.xml)
#   make test   install dependencies, build, run the whole test suite
#   make doc    the API reference of the public headers (build/doc/api/html)
BUILD ?= build
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

.PHONY: all deps configure build run test bench doc clean

all: build

deps:
	bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	mpirun -np $(NP) $(BUILD)/bin/signorini $(INPUT) --output $(OUTPUT)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

doc: build
	cmake --build $(BUILD) --target doc

clean:
	rm -rf $(BUILD)
