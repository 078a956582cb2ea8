# gdsmc: the two commands of the README, plus their parts.
#   make verify   install missing packages, configure, build, run the quick suite
#   make test     the same set-up, then every test, and the unit tests again
#                 in an address+undefined sanitizer build
BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
CMAKE_FLAGS ?=
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

# Debian 12 packages the build needs (SPEC: never vendored).
PACKAGES = cmake make gcc pkg-config libgsl-dev libsundials-dev libcmocka-dev \
           librandom123-dev libinih-dev gnuplot-nox

.PHONY: all deps build verify test test-sanitize clean

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
	cmake -S . -B $(SANITIZE_BUILD) -DGDSMC_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug $(CMAKE_FLAGS)
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	ctest --test-dir $(SANITIZE_BUILD) -L unit -j $(JOBS) --output-on-failure

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD)
