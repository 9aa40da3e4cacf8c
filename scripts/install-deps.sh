#!/usr/bin/env bash
# Installs the Debian 12 packages seflex needs to build, test and run its demo.
# Does nothing when everything is present; uses sudo when not root.
#
# ParaView's Python (python3-paraview) conflicts with python3-vtk9, which libvtk9-dev needs, so it
# is not installed through dpkg: its Debian package is fetched with `apt-get download` and unpacked
# into a private prefix (SEFLEX_PARAVIEW_PY, default /opt/seflex/paraview-python) used only by
# scripts/pvrender.sh. The `paraview` package itself (pvbatch) installs normally.
#
# petsc-dev and slepc-dev (PETSc 3.18 with MUMPS, SLEPc 3.18) and MPI (OpenMPI through
# mpi-default-dev/-bin) build the distributed backend (SEFLEX_MPI, docs/distributed.md); without
# them the build is serial and everything else works.
#
# clang 14 (the `clang` package: clang-14 and the clang/clang++ links) with libclang-rt-14-dev builds
# the sanitizer and fuzzing stage of `scripts/bootstrap.sh test` (build-fuzz/): libclang-rt-14-dev
# holds the ASan/UBSan runtimes and libFuzzer itself (libclang_rt.fuzzer*.a, what -fsanitize=fuzzer
# links), so Debian's separate libfuzzer-14-dev (libFuzzer.a for other compilers) is not needed.
#
# python3-dev and pybind11-dev build the Python module (python/, docs/python.md) for Debian's
# /usr/bin/python3; python3-pytest runs its tests (tests/python). Without them the module is skipped.
set -euo pipefail

packages=(
  g++ cmake make ninja-build pkg-config git ccache
  clang clang-14 libclang-rt-14-dev llvm-14
  libeigen3-dev libspectra-dev libarpack2-dev libmetis-dev libsuitesparse-dev libopenblas-dev
  libgmsh-dev gmsh libvtk9-dev libyaml-cpp-dev libgtest-dev nettle-dev
  python3 python3-numpy python3-scipy python3-matplotlib python3-dev pybind11-dev python3-pytest
  paraview xvfb xauth
  petsc-dev slepc-dev mpi-default-dev mpi-default-bin
)
pv_prefix="${SEFLEX_PARAVIEW_PY:-/opt/seflex/paraview-python}"

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
need_pv=0
[ -f "$pv_prefix/usr/lib/python3/dist-packages/paraview/simple.py" ] || need_pv=1

if [ ${#missing[@]} -eq 0 ] && [ $need_pv -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present; nothing to do"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1
  fi
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

if [ $need_pv -eq 1 ]; then
  echo "install-deps: unpacking python3-paraview into $pv_prefix"
  tmp=$(mktemp -d)
  chmod 777 "$tmp"
  (cd "$tmp" && apt-get download -q python3-paraview)
  $SUDO mkdir -p "$pv_prefix"
  $SUDO dpkg-deb -x "$tmp"/python3-paraview_*.deb "$pv_prefix"
  rm -rf "$tmp"
fi
echo "install-deps: done"
