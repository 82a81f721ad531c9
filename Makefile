# mechmat — one non-recursive Makefile.
#
#   make run      install what is missing, build, serve on http://127.0.0.1:$(PORT)
#   make test     install what is missing, build, run every test
#   make asan     the whole suite under AddressSanitizer + UBSan (build/asan)
#   make bench    benchmarks that print figures
#   make a11y     axe-core on the catalog and every exercise page, desktop and phone
#   make deps     only install what is missing (Debian packages, npm packages)
#   make flags    print the settings
#   make tsan     the concurrent tests under ThreadSanitizer (build/tsan)
#   make install  PREFIX=/usr/local DESTDIR=: the server, web/, theory texts,
#                 browser packages and deploy files (README "Hosting it for a class")
#   make failover nginx in front of two instances, one killed under load
#   make fuzz-long every libFuzzer target for FUZZ_CPU_SECONDS (3600) of CPU
#   make answers every exercise's answers (defaults + ANSWERS_N draws) to diff
#                 before and after a refactoring
#   make ref      chapter 1's printed numbers against 60-digit references (tests/ref)

# ---- settings ---------------------------------------------------------------
BUILD    ?= build
PORT     ?= 8080
HOST     ?= 127.0.0.1
SANITIZE ?=
TSAN     ?=
PREFIX   ?= /usr/local
DESTDIR  ?=
CC       := gcc
CXX      := g++

PKGS     := libmicrohttpd libcjson lapacke fftw3 muparser libcmark libdeflate nettle
TESTPKGS := cmocka libcurl zlib

WARN     := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes -Wwrite-strings -Wundef -Wformat=2 \
            -Wno-format-nonliteral
OPT      := -O2 -g
ifneq ($(FUZZ),)
OPT      += -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
LDSAN    := -fsanitize=address,undefined
else ifneq ($(TSAN),)
OPT      += -fsanitize=thread -fno-omit-frame-pointer
LDSAN    := -fsanitize=thread
else ifneq ($(SANITIZE),)
OPT      += -fsanitize=address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
LDSAN    := -fsanitize=address,undefined
endif

PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) $(TESTPKGS) 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs $(PKGS) 2>/dev/null)
TEST_LIBS  = $(shell pkg-config --libs $(TESTPKGS) 2>/dev/null)

CPPFLAGS := -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -Isolvers -Iexercises -Iserver
CFLAGS   := -std=c11 $(OPT) $(WARN) -MMD -MP
CXXFLAGS := -std=c++17 $(OPT) -fno-sanitize=vptr -Wall -Wextra -Werror -MMD -MP
LDLIBS    = $(PKG_LIBS) -lfmt -lstdc++ -lm -lpthread

# ---- sources ----------------------------------------------------------------
SOLVER_SRC := $(sort $(wildcard solvers/*.c))
EX_SRC     := $(sort $(wildcard exercises/*.c exercises/*/*.c))
SERVER_SRC := $(sort $(filter-out server/main.c,$(wildcard server/*.c)))
SERVER_CXX := $(sort $(wildcard server/*.cc))
UNIT_SRC   := $(sort $(wildcard tests/unit/test_*.c))
FUZZ_NAMES := $(patsubst tests/fuzz/fuzz_%.c,%,$(sort $(wildcard tests/fuzz/fuzz_*.c)))
BENCH_SRC  := $(sort $(wildcard tests/bench/bench_*.c))

obj = $(patsubst %.c,$(BUILD)/obj/%.o,$(patsubst %.cc,$(BUILD)/obj/%.o,$(1)))

SOLVER_LIB := $(BUILD)/libmm_solvers.a
EX_LIB     := $(BUILD)/libmm_exercises.a
SERVER_LIB := $(BUILD)/libmm_server.a
LIBS       := $(SERVER_LIB) $(EX_LIB) $(SOLVER_LIB)
SERVER_BIN := $(BUILD)/mechmat-server
UNIT_BINS  := $(patsubst tests/unit/%.c,$(BUILD)/tests/%,$(UNIT_SRC))
BENCH_BINS := $(patsubst tests/bench/%.c,$(BUILD)/bench/%,$(BENCH_SRC))
REPLAY_BINS:= $(patsubst %,$(BUILD)/tests/test_fuzz_%,$(FUZZ_NAMES))
FUZZ_BINS  := $(patsubst %,$(BUILD)/fuzz/fuzz_%,$(FUZZ_NAMES))
FUZZ_SECONDS ?= 60

ALL_OBJ := $(call obj,$(SOLVER_SRC) $(EX_SRC) $(SERVER_SRC) $(SERVER_CXX) server/main.c)

# object files are never removed as intermediates (a test's .o, made on the
# way to its binary, would be rebuilt by the next make)
.SECONDARY:

.PHONY: all run test asan bench deps flags clean tests loadtest fuzz fuzz-bins valgrind tsan install study \
        failover fuzz-long a11y ref answers
.DEFAULT_GOAL := all

all: $(SERVER_BIN)

tests: $(SERVER_BIN) $(UNIT_BINS) $(REPLAY_BINS)

# ---- build rules ------------------------------------------------------------
$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(PKG_CFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.cc
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

$(SOLVER_LIB): $(call obj,$(SOLVER_SRC))
	@rm -f $@
	ar rcs $@ $^

$(EX_LIB): $(call obj,$(EX_SRC))
	@rm -f $@
	ar rcs $@ $^

$(SERVER_LIB): $(call obj,$(SERVER_SRC) $(SERVER_CXX))
	@rm -f $@
	ar rcs $@ $^

$(SERVER_BIN): $(call obj,server/main.c) $(LIBS)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/unit/%.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS) $(TEST_LIBS)

$(BUILD)/bench/%: $(BUILD)/obj/tests/bench/%.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS) $(TEST_LIBS) -lgsl

# a bare libmicrohttpd endpoint: the ceiling the server is measured against
$(BUILD)/bench/bare_mhd: tests/bench/bare_mhd.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(PKG_CFLAGS) $(CFLAGS) -o $@ $< $(LDSAN) -lmicrohttpd -lpthread

# a fuzz target's committed corpus, replayed once as a regression test
$(BUILD)/tests/test_fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/replay.c $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/unit $(PKG_CFLAGS) $(filter-out -MMD -MP,$(CFLAGS)) -DFUZZ_NAME='"$*"' \
	    -o $@ tests/fuzz/fuzz_$*.c tests/fuzz/replay.c $(LIBS) $(LDSAN) $(LDLIBS) $(TEST_LIBS)

# libFuzzer binaries (clang; make fuzz builds them in build/fuzz)
$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(PKG_CFLAGS) $(filter-out -MMD -MP,$(CFLAGS)) -fsanitize=fuzzer \
	    -o $@ $< $(LIBS) $(LDSAN) $(LDLIBS)

fuzz-bins: $(FUZZ_BINS)

# README's example exercise, compiled and run by tests/unit/test_readme.c
$(BUILD)/readme/readme_example.c: README.md
	@mkdir -p $(dir $@)
	awk '/<!-- readme-example: end -->/ {f = 0} f && !/^```/ {print} /<!-- readme-example: begin -->/ {f = 1}' $< > $@

$(BUILD)/obj/tests/unit/test_readme.o: $(BUILD)/readme/readme_example.c
$(BUILD)/obj/tests/unit/test_readme.o: CPPFLAGS += -I$(BUILD)/readme

$(BUILD)/load/loadtool: $(BUILD)/obj/tests/load/loadtool.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS) $(TEST_LIBS)

# every exercise's answers at its defaults and ANSWERS_N draws, timings
# blanked (tests/tools/answers.c): run before and after a refactoring, diff
ANSWERS_N ?= 20
$(BUILD)/tools/answers: $(BUILD)/obj/tests/tools/answers.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS)

answers: $(BUILD)/tools/answers
	@$(BUILD)/tools/answers -n $(ANSWERS_N) > $(BUILD)/answers.txt
	@echo "answers: $$(wc -l < $(BUILD)/answers.txt) lines in $(BUILD)/answers.txt ($$(md5sum < $(BUILD)/answers.txt | cut -c1-12))"

# every exercise's checks at STUDY_N seeded draws inside its limits (minutes):
# a check that fails there, or an answer lost (422, 500), fails the study;
# the worst use of each check's tolerance is in test-output/study.log
STUDY_N ?= 2000
study: deps
	@$(MAKE) --no-print-directory $(BUILD)/tools/answers
	@mkdir -p test-output
	@bash -o pipefail -c '$(BUILD)/tools/answers --checks -n $(STUDY_N) > test-output/study.log; rc=$$?; \
	  grep -E "^   (FAILED|status [0-9]+ \(an answer lost\))" test-output/study.log | cut -c1-300; tail -n 1 test-output/study.log; exit $$rc'

# the reference harness's draws (tests/ref/num_ref.py; make ref)
$(BUILD)/ref/num_draws: $(BUILD)/obj/tests/ref/num_draws.o $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(LDSAN) -o $@ $^ $(LDLIBS)

$(BUILD)/obj/tests/%.o: tests/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests $(PKG_CFLAGS) $(CFLAGS) -c $< -o $@

# ---- the two commands -------------------------------------------------------
deps:
	@scripts/deps.sh

run: deps
	@$(MAKE) --no-print-directory all
	$(SERVER_BIN) --host $(HOST) --port $(PORT)

test:
	@scripts/deps.sh --test
	@$(MAKE) --no-print-directory tests
	@BUILD=$(BUILD) tests/run.sh

# axe-core on the catalog and every exercise page at 1280 and 390 px (minutes;
# make test keeps a representative set)
a11y:
	@scripts/deps.sh --test
	@$(MAKE) --no-print-directory all
	@mkdir -p test-output
	@MM_SERVER=$(SERVER_BIN) bash -o pipefail -c 'node tests/web/a11y.mjs 2>test-output/a11y-server.log | tee test-output/a11y.log'

asan:
	@scripts/deps.sh
	@$(MAKE) --no-print-directory BUILD=build/asan SANITIZE=1 tests
	@BUILD=build/asan ASAN=1 tests/run.sh

valgrind: deps
	@$(MAKE) --no-print-directory tests
	@BUILD=$(BUILD) tests/valgrind.sh

bench: deps
	@$(MAKE) --no-print-directory all $(BENCH_BINS) $(BUILD)/bench/bare_mhd $(BUILD)/load/loadtool
	@BUILD=$(BUILD) tests/bench/run.sh

# make fuzz: each target for FUZZ_SECONDS (default 60) from its committed
# corpus; new inputs go to build/fuzz/corpus-NAME, crashes to build/fuzz/.
fuzz: deps
	@$(MAKE) --no-print-directory BUILD=build/fuzz CC=clang CXX=clang++ FUZZ=1 fuzz-bins
	@FUZZ_SECONDS=$(FUZZ_SECONDS) tests/fuzz/run.sh

loadtest:
	@scripts/deps.sh --test
	@$(MAKE) --no-print-directory all $(BUILD)/load/loadtool $(BUILD)/bench/bare_mhd
	@BUILD=$(BUILD) tests/load/run.sh
	@BUILD=$(BUILD) tests/load/class_start.sh

# The tests that run threads against each other, under ThreadSanitizer: the
# cache's single flight, the server's event threads and workers (the HTTP
# tests start build/tsan/mechmat-server).  Not test_linalg: ThreadSanitizer
# finds a race inside Debian's serial OpenBLAS 0.3.21 there (two threads
# writing one buffer in dgemm_oncopy), a library matter reported apart.
TSAN_TESTS := test_cache test_http test_http_cache test_badinput
tsan:
	@scripts/deps.sh
	@$(MAKE) --no-print-directory BUILD=build/tsan TSAN=1 build/tsan/mechmat-server \
	    $(patsubst %,build/tsan/tests/%,$(TSAN_TESTS))
	@mkdir -p test-output; fail=0; \
	for t in $(TSAN_TESTS); do \
	  echo "== tsan $$t"; \
	  MM_SERVER=build/tsan/mechmat-server ASAN=1 \
	  TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1" \
	    build/tsan/tests/$$t > test-output/tsan-$$t.log 2>&1 || fail=1; \
	  grep -E '^\[  (PASSED|FAILED)' test-output/tsan-$$t.log | sed 's/^/   /'; \
	  if grep -q 'WARNING: ThreadSanitizer' test-output/tsan-$$t.log; then \
	    grep -A12 'WARNING: ThreadSanitizer' test-output/tsan-$$t.log | head -40; fail=1; fi; \
	done; \
	if [ $$fail = 0 ]; then echo "tsan: clean"; else echo "tsan: FAILED"; exit 1; fi

# every printed number of the chapter-1 exercises against its exact value
# (mpmath, exact rationals) over the defaults and 200 draws; minutes, not in
# `make test`.  REF_ARGS="--only num-eigen --draws 20" for a part.
ref:
	@scripts/deps.sh --ref
	@$(MAKE) --no-print-directory all $(BUILD)/ref/num_draws
	@BUILD=$(BUILD) tests/ref/run.sh

# make install: everything the server needs at run time, nothing else.
install: all
	@deploy/install.sh "$(DESTDIR)" "$(PREFIX)" "$(SERVER_BIN)"

# nginx in front of two instances on free loopback ports; one killed under load
failover:
	@scripts/deps.sh --test
	@$(MAKE) --no-print-directory all $(BUILD)/load/loadtool
	@BUILD=$(BUILD) tests/load/failover.sh

fuzz-long: deps
	@$(MAKE) --no-print-directory BUILD=build/fuzz CC=clang CXX=clang++ FUZZ=1 fuzz-bins
	@FUZZ_CPU_SECONDS=$${FUZZ_CPU_SECONDS:-3600} tests/fuzz/long.sh

flags:
	@echo "CC       = $(CC)"
	@echo "CPPFLAGS = $(CPPFLAGS) $(PKG_CFLAGS)"
	@echo "CFLAGS   = $(CFLAGS)"
	@echo "LDLIBS   = $(LDLIBS)"
	@echo "BUILD    = $(BUILD)"

clean:
	rm -rf build test-output

-include $(ALL_OBJ:.o=.d) $(patsubst tests/%.c,$(BUILD)/obj/tests/%.d,$(UNIT_SRC) $(BENCH_SRC))
