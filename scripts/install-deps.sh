#!/usr/bin/env bash
# The one list of Debian packages flexmb needs (build, tests, benchmarks,
# Python bindings, cross-check tools). Idempotent: installs only what is
# missing, so a second run costs a dpkg query and nothing else.
set -euo pipefail

PACKAGES=(
  # toolchain
  g++ cmake ninja-build make pkg-config
  # libFuzzer targets for the readers (make fuzz)
  clang
  # LLVM linker: shorter links of the sanitizer and fuzz programs (CMakeLists.txt)
  lld
  # numerics
  libeigen3-dev libsuitesparse-dev libopenblas-dev libspectra-dev
  # input / output / command line
  libyaml-cpp-dev libhdf5-dev libcli11-dev libfmt-dev libmuparser-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # python bindings and plots (Debian's /usr/bin/python3)
  pybind11-dev python3-dev python3-numpy python3-matplotlib
  # peer codes for cross-checks
  calculix-ccx gmsh
  # Python module tests (ctest label python; docs/python.md)
  python3-pytest
  # parameter studies on a local or remote Dask cluster (flexmb study; docs/studies.md)
  python3-distributed
  # the study files are rewritten with PyYAML (python/flexmb/studyfile.py);
  # the study table is also written as HDF5 (study.h5) with pandas and PyTables
  python3-yaml python3-pandas python3-tables
  # the distributed reduction (flexmb reduce --backend petsc under mpirun;
  # flexmb/reduction/petsc/): PETSc with MUMPS, SLEPc, Open MPI
  petsc-dev slepc-dev libmumps-dev openmpi-bin libopenmpi-dev
  # ParaView opens what we write (pvbatch in python/tests/test_paraview.py) and
  # renders the truck's follow-camera views under a virtual X server
  # (examples/truck_lane_change/view_animation.py)
  python3-paraview xvfb xauth
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
