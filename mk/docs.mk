# docs.mk -- the documentation's own test.
#
# tests/test_docs.sh: README.md at most 450 lines (a manual; topics live in
# docs/), and every relative link of README.md and docs/*.md reaches its
# file and, for FILE.md#anchor or #anchor, its heading (GitHub's ids).
TEST_SCRIPTS += tests/test_docs.sh
