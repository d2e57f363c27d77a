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
  cargo fuzz build -O --sanitizer "$SANITIZER" ${CARGO_FUZZ_ARGS:-}
else
  cargo fuzz build -O --sanitizer none
fi
triple=$(rustc -vV | sed -n 's/^host: //p')
for target in $(cargo fuzz list); do
  cp "fuzz/target/$triple/release/$target" "$OUT/$target"
  if [ -d "fuzz/corpus/$target" ]; then
    (cd "fuzz/corpus/$target" && python3 -m zipfile -c "$OUT/${target}_seed_corpus.zip" .)
    test -s "$OUT/${target}_seed_corpus.zip"
  fi
done
echo "built: $(cargo fuzz list | tr '\n' ' ')-> $OUT"
