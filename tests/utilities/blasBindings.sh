#!/bin/bash
# Every BLAS routine the tools call is OpenBLAS's (CMakeLists.txt, "One BLAS in every
# process"): each tool in BUILD_DIR/bin, each test program in BUILD_DIR/tests and each
# benchmark in BUILD_DIR/bench (where built) is started
# with LD_BIND_NOW, so that the dynamic linker binds all its symbols before main and reports
# where (LD_DEBUG=bindings); every binding of a BLAS routine (sgemm_, dgemm_, dsyrk_, ...)
# must go to a library whose real path names openblas. Before the fix, policyMesh bound
# LibTorch's sgemm_ to ATLAS's libf77blas.so.3.
#   blasBindings.sh BUILD_DIR
set -u
build="${1:?usage: blasBindings.sh BUILD_DIR}"
blasSymbol='symbol `[sdcz](gemm|gemv|syrk|trsm|trmm|symm|axpy|dot|scal|copy|nrm2)_'"'"
failures=0 checked=0
for exe in "$build"/bin/* "$build"/tests/*Tests "$build"/bench/*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  case "$exe" in */bin/*) option=-help ;; */tests/*) option=--gtest_list_tests ;; *) option=--help ;; esac
  # (the bindings are made before main: a benchmark that starts work on --help is stopped)
  targets="$(LD_BIND_NOW=1 LD_DEBUG=bindings timeout 20 "$exe" "$option" 2>&1 >/dev/null |
    grep -E "$blasSymbol" | sed -n 's/.* to \([^ ]*\) \[.*/\1/p' | sort -u)"
  [ -n "$targets" ] || continue
  checked=$((checked + 1))
  for lib in $targets; do
    case "$(readlink -f "$lib")" in
      *openblas*) ;;
      *) echo "blasBindings: $(basename "$exe") binds BLAS routines to $lib ($(readlink -f "$lib")), not OpenBLAS"
         failures=$((failures + 1)) ;;
    esac
  done
done
# LibTorch's matrix products at least must have been seen, else the check proved nothing.
for tool in policyMesh policyTrain; do
  LD_BIND_NOW=1 LD_DEBUG=bindings "$build/bin/$tool" -help 2>&1 >/dev/null | grep -q 'libtorch_cpu.*symbol `sgemm_'"'" ||
    { echo "blasBindings: no binding of LibTorch's sgemm_ seen in $tool (LD_DEBUG not working?)"; failures=$((failures + 1)); }
done
echo "blasBindings: $checked programs bind BLAS routines; $failures bindings outside OpenBLAS"
[ "$failures" -eq 0 ]
