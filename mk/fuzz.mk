# fuzz.mk -- libFuzzer harnesses for every parser of outside input (fuzz/).
#
#   make fuzz          each harness FUZZ_SECONDS (default 300) from its seed
#                      corpus (fuzz/corpus/NAME/); one line per harness with
#                      the executions and executions per second; on a crash,
#                      leak or sanitizer report the reproducer's path and a
#                      non-zero exit (scripts/fuzz.sh).
#   make test          tests/test_fuzz.sh: replays fuzz/regress/NAME/ and
#                      the seeds under ASan/UBSan, then 20 s per harness.
#
# The harnesses are built with clang (Debian, scripts/setup.sh) and
# -fsanitize=fuzzer,address,undefined; the library sources they use are
# compiled with -fsanitize=fuzzer-no-link,address,undefined into their own
# archive, so the coverage the fuzzer steers by covers the parsers.  No
# Verilated model is linked: the library files a harness pulls in may
# reference one (testfloat.c, engine_rtl.c) on paths the harness never
# takes, and fuzz/fuzz_nomodel.c gives the linker those entry points, each
# stopping the process if it were ever called.

FUZZ_CC       ?= clang
FUZZ_SECONDS  ?= 300
FUZZ_NAMES    := asm image scene model testfloat options
FUZZ_DIR      := $(BUILD)/fuzz
FUZZ_BINS     := $(addprefix $(FUZZ_DIR)/fuzz_,$(FUZZ_NAMES))
FUZZ_SAN      := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
# The project's C flags, for clang (-Wno-string-plus-int: image.h builds
# FP3_IN_NAMES_TEXT as a string literal plus 1, to skip its leading space).
FUZZ_CFLAGS   := -O1 -g $(CSTD) $(CWARN) -Wno-string-plus-int -ffp-contract=off -fno-fast-math \
                 $(SW_INC) $(SW_CPPFLAGS)
FUZZ_COMMON   := fuzz/fuzz_common.c fuzz/fuzz_nomodel.c
FUZZ_LIB_OBJS := $(patsubst sw/%.c,$(FUZZ_DIR)/sw/%.o,$(SW_LIB_SRCS))
FUZZ_LIB      := $(FUZZ_DIR)/libfp3-fuzz.a

$(FUZZ_DIR)/sw/%.o: sw/%.c | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_SAN) -fsanitize=fuzzer-no-link -MMD -MP -c $< -o $@

$(FUZZ_LIB): $(FUZZ_LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

-include $(FUZZ_LIB_OBJS:.o=.d)

$(FUZZ_DIR)/fuzz_%: fuzz/fuzz_%.c $(FUZZ_COMMON) fuzz/fuzz_common.h $(FUZZ_LIB) | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -Ifuzz $(FUZZ_SAN) -fsanitize=fuzzer \
	  -o $@ $< $(FUZZ_COMMON) $(FUZZ_LIB) $(LDLIBS_SW)

.PHONY: fuzz fuzz-build
## fuzz: run each libFuzzer harness (fuzz/fuzz_*.c) FUZZ_SECONDS (default 300); executions, exec/s, a crash's reproducer
fuzz: $(FUZZ_BINS)
	bash scripts/fuzz.sh $(FUZZ_SECONDS) $(FUZZ_DIR) $(FUZZ_NAMES)

## fuzz-build: build the libFuzzer harnesses only (build/fuzz/fuzz_NAME; a file argument replays it)
fuzz-build: $(FUZZ_BINS)

# make test: tests/test_fuzz.sh replays the regression inputs and fuzzes
# each harness FUZZ_TEST_SECONDS.
export FUZZ_BIN_DIR := $(abspath $(FUZZ_DIR))
export FUZZ_HARNESSES := $(FUZZ_NAMES)
TEST_SCRIPTS += tests/test_fuzz.sh
test-build: $(FUZZ_BINS)
