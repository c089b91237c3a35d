#!/usr/bin/env bash
# setup.sh -- install the Debian packages FP3 needs, and only those that are missing.
#
# Called by `make` when a tool or library is not found (see the Makefile's
# `setup` target); safe to run by hand and to run again. Each package is
# checked with dpkg first, so a machine that has everything installs nothing.
#
#   verilator    Verilog -> C++ models (make sim, make test)
#   iverilog     Icarus Verilog, waveform test bench (make wave)
#   yosys        synthesis (make synth)
#   libgsl-dev   GNU Scientific Library, numerical references
#   libcmocka-dev  C unit-test framework used by tests/
#   zlib1g-dev   gzip-compressed TestFloat vectors
#   pkg-config   locating the libraries above
set -euo pipefail

pkgs=(verilator iverilog yosys libgsl-dev libcmocka-dev zlib1g-dev pkg-config g++ make)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all required packages are installed"
  exit 0
fi
echo "setup: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
