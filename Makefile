# gdsmc: the two commands of the README, plus their parts.
#   make verify   install missing packages, configure, build, run the quick suite
#   make test     the same set-up, then every test, and the unit tests and the
#                 quick suite again in an address+undefined sanitizer build
#   make fuzz     libFuzzer (clang, address sanitizer) over scene parsing and
#                 validation (corpus verify/cases/scenes), over the solver
#                 protocol's result reader (corpus tests/fuzz/results) and over
#                 case files (corpus verify/cases/scenes/*.case), each for
#                 FUZZ_SECONDS (default 600)
#   make test-mpi optional: installs OpenMPI, builds $(MPI_BUILD) with GDSMC_MPI=ON
#                 and checks that 2 ranks give the numbers of 1 process
BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
MPI_BUILD ?= build-mpi
FUZZ_SECONDS ?= 600
CMAKE_FLAGS ?=
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

# Debian 12 packages the build needs (installed from Debian, never vendored).
PACKAGES = cmake make gcc pkg-config libgsl-dev libsundials-dev libcmocka-dev \
           librandom123-dev libinih-dev gnuplot-nox python3 python3-numpy
FUZZ_PACKAGES = clang libomp-dev
MPI_PACKAGES = libopenmpi-dev openmpi-bin

.PHONY: all deps build verify test test-sanitize fuzz test-mpi clean

all: build

# Install what is missing when root; otherwise print the exact command and stop.
deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "installing:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	  else \
	    echo "missing packages; run:"; echo "  sudo apt-get install -y$$missing"; exit 1; \
	  fi; \
	fi

build: deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)
	cmake --build $(BUILD) -j $(JOBS)

verify: build
	$(BUILD)/gdsmc verify --suite quick

test: build
	ctest --test-dir $(BUILD) -j $(JOBS) --output-on-failure
	$(MAKE) test-sanitize

test-sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DGDSMC_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	ctest --test-dir $(SANITIZE_BUILD) -L unit -j $(JOBS) --output-on-failure
	$(SANITIZE_BUILD)/gdsmc verify --suite quick --out $(SANITIZE_BUILD)/reports

# The fuzzers' corpora grow in $(FUZZ_BUILD)/corpus (seeded from verify/cases/scenes),
# $(FUZZ_BUILD)/corpus-result and $(FUZZ_BUILD)/corpus-case; crashes are written to
# $(FUZZ_BUILD)/crash-*, $(FUZZ_BUILD)/result-crash-* and $(FUZZ_BUILD)/case-crash-*.
fuzz:
	$(MAKE) deps PACKAGES="$(PACKAGES) $(FUZZ_PACKAGES)"
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_C_COMPILER=clang -DGDSMC_FUZZ=ON $(CMAKE_FLAGS)
	cmake --build $(FUZZ_BUILD) --target fuzz_scene fuzz_result fuzz_case -j $(JOBS)
	mkdir -p $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/corpus-result $(FUZZ_BUILD)/corpus-case
	cp -n verify/cases/scenes/*.ini $(FUZZ_BUILD)/corpus/
	cp -n tests/fuzz/results/* $(FUZZ_BUILD)/corpus-result/
	cp -n verify/cases/scenes/*.case $(FUZZ_BUILD)/corpus-case/
	$(FUZZ_BUILD)/fuzz_scene -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -timeout=10 \
	  -artifact_prefix=$(FUZZ_BUILD)/ $(FUZZ_BUILD)/corpus
	$(FUZZ_BUILD)/fuzz_result -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -timeout=10 \
	  -artifact_prefix=$(FUZZ_BUILD)/result- $(FUZZ_BUILD)/corpus-result
	$(FUZZ_BUILD)/fuzz_case -max_total_time=$(FUZZ_SECONDS) -max_len=16384 -timeout=10 \
	  -artifact_prefix=$(FUZZ_BUILD)/case- $(FUZZ_BUILD)/corpus-case

# Ensembles across MPI ranks (docs/running.md); only the
# executable is built, and only the tests labelled mpi run.
test-mpi:
	$(MAKE) deps PACKAGES="$(PACKAGES) $(MPI_PACKAGES)"
	cmake -S . -B $(MPI_BUILD) -DGDSMC_MPI=ON $(CMAKE_FLAGS)
	cmake --build $(MPI_BUILD) --target gdsmc -j $(JOBS)
	ctest --test-dir $(MPI_BUILD) -L mpi --output-on-failure

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD) $(MPI_BUILD)
