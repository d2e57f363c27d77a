#!/bin/bash -eu
# Builds every fuzz target of rayoracle for ClusterFuzzLite / OSS-Fuzz and
# copies the binaries, with their seed corpora, to $OUT.
#
# Inside the ClusterFuzzLite image, SANITIZER and CARGO_FUZZ_ARGS come from
# the environment. Outside it (.ci/run exercises this script on stable,
# without Docker), set OUT to a directory and it builds with
# --sanitizer none.
# `bash build.sh` ignores the -eu above, so set it again here: a failed copy
# or zip must fail the build, not scroll past.
set -euo pipefail
cd "${SRC:-$(dirname "$0")/..}/rayoracle" 2>/dev/null || cd "$(dirname "$0")/.."
OUT=${OUT:?set OUT to the output directory}
mkdir -p "$OUT"
# Absolute, because the corpus zip below is written from inside the corpus dir.
OUT=$(cd "$OUT" && pwd)
if [ -n "${SANITIZER:-}" ] && [ "${SANITIZER}" != "none" ]; then
  args=(--sanitizer "$SANITIZER" ${CARGO_FUZZ_ARGS:-})
else
  args=(--sanitizer none)
fi
# The binaries are those `cargo fuzz run` builds (.ci/run, fuzz/campaign):
# optimised, with debug assertions and overflow checks (-O -a); the kernel
# targets without the compare hooks, in their own target directory
# (fuzz/kernel-targets), the parsing targets with them. So the fuzz step of
# .ci/run rebuilds nothing.
triple=$(rustc -vV | sed -n 's/^host: //p')
for target in $(cargo fuzz list); do
  flags=$(fuzz/kernel-targets "$target")
  dir=$(sed -n 's/.*--target-dir \([^ ]*\).*/\1/p' <<<"$flags")
  (cd fuzz && cargo fuzz build -O -a "${args[@]}" $flags "$target")
  cp "fuzz/${dir:-target}/$triple/release/$target" "$OUT/$target"
  # The libFuzzer options, as ClusterFuzz reads them: $OUT/TARGET.options.
  options=$(fuzz/kernel-targets --options "$target")
  if [ -n "$options" ]; then
    printf '[libfuzzer]\n' >"$OUT/$target.options"
    for o in $options; do
      o=${o#-}
      printf '%s = %s\n' "${o%%=*}" "${o#*=}" >>"$OUT/$target.options"
    done
  fi
  if [ -d "fuzz/corpus/$target" ]; then
    (cd "fuzz/corpus/$target" && python3 -m zipfile -c "$OUT/${target}_seed_corpus.zip" .)
    test -s "$OUT/${target}_seed_corpus.zip"
  fi
done
echo "built: $(cargo fuzz list | tr '\n' ' ')-> $OUT"
