#!/usr/bin/env bash
# The per-instruction-set element kernels (src/fe/element_kernel_avx2.cpp,
# _avx512.cpp) are compiled with -mavx2 / -mavx512f.  Any code they define
# outside their own namespaces (drawbend::fe::avx2:: and the materials' lane
# twins' drawbend::material::lanes::avx2::; ::avx512:: alike) is a weak or
# global symbol that the linker may keep for EVERY caller: an AVX-512 copy of
# a shared inline function would then crash an AVX2-only machine with an
# illegal instruction.  This test lists the code symbols each kernel object
# defines and fails on any outside its namespace.  Data symbols (constants)
# are allowed: they hold no instructions.
# Usage: check_isa_symbols.sh LIBDRAWBEND_FE.a
# Expected: "isa symbols ok" and exit 0; otherwise the offending symbols, exit 1.
set -euo pipefail
lib=$1
command -v nm >/dev/null || { echo "nm not found"; exit 77; }
members=$(ar t "$lib" | grep -E '^element_kernel_avx(2|512)\.cpp\.o$' || true)
[ -n "$members" ] || { echo "no per-ISA kernel objects in $lib (not x86-64): nothing to check"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bad=0
for m in $members; do
  isa=${m#element_kernel_}
  isa=${isa%.cpp.o}
  (cd "$tmp" && ar x "$lib" "$m")
  # Code symbols: T/t global/local text, W weak (inline functions, templates), i indirect.
  out=$(nm -C --defined-only "$tmp/$m" | awk '$2 ~ /^[TWi]$/' | cut -d' ' -f3- | grep -v "::${isa}::" || true)
  if [ -n "$out" ]; then
    echo "$m defines code outside the ::${isa}:: namespaces (compiled for ${isa}; the linker may use it everywhere):"
    echo "$out" | sed 's/^/  /'
    bad=1
  fi
done
[ $bad -eq 0 ] && echo "isa symbols ok: $(echo $members | wc -w) kernel objects"
exit $bad
