# structure.mk -- checks of the project's shape rather than its function:
# sw/'s layers include only downwards (tests/test_layers.sh), and `make
# help` lists every .PHONY target (tests/test_make_help.sh).
TEST_SCRIPTS += tests/test_layers.sh tests/test_make_help.sh
