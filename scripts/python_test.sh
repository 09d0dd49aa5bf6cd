#!/usr/bin/env bash
# The Python package (python/, PyO3 + maturin): build the wheel, install it into a fresh virtual
# environment, run its pytest suite (python/tests: every function, every bundled case against
# `flexfem run`/`sweep`) and its examples (python/examples). `.ci/run` runs it after the Rust
# tests.
#
# The wheel is built in this repository's target/ with the release profile, so it links the
# flexfem library `cargo build --release` compiled (only the bindings and PyO3/numpy compile).
#
# Exit status: 0 when everything passed, or SKIPPED (printed with the reason) when there is no
# python3 with venv, or pip cannot install the build and test packages (no network); 1 when a
# build, a test or an example failed.
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
START=$SECONDS

skip() {
    echo "python_test: SKIPPED ($1)"
    exit 0
}

PYTHON=${PYTHON:-python3}
command -v "$PYTHON" >/dev/null 2>&1 || skip "no $PYTHON"
VENV=$(mktemp -d "${TMPDIR:-/tmp}/flexfem-venv.XXXXXX")
trap 'rm -rf "$VENV"' EXIT
"$PYTHON" -m venv "$VENV" >/dev/null 2>&1 || skip "$PYTHON has no working venv module"
PY=$VENV/bin/python
"$PY" -m pip install --quiet --disable-pip-version-check \
    "maturin>=1.5,<2" numpy scipy pytest pandas matplotlib control \
    || skip "pip could not install maturin and the test packages (network?)"
echo "python_test: virtual environment ready ($((SECONDS - START)) s)"

set -e
cargo build --release --bin flexfem
rm -rf target/wheels
# Built for the base interpreter (the same Python as the venv's): its path stays the same from
# run to run, so PyO3's build configuration, and with it the compiled bindings, stay fresh.
"$VENV/bin/maturin" build --release --manifest-path python/Cargo.toml --out target/wheels --compatibility linux \
    --interpreter "$PYTHON"
"$PY" -m pip install --quiet --disable-pip-version-check target/wheels/flexfem-*.whl
echo "python_test: wheel built and installed ($((SECONDS - START)) s)"

# From outside the source folder, so `import flexfem` is the installed wheel.
cd "$VENV"
FLEXFEM_BIN=$ROOT/target/release/flexfem "$PY" -m pytest -q -p no:cacheprovider "$ROOT/python/tests"
out=$VENV/examples
for example in "$ROOT"/python/examples/*.py; do
    echo "python_test: example $(basename "$example")"
    "$PY" "$example" "$out"
done
echo "python_test: passed ($((SECONDS - START)) s)"
