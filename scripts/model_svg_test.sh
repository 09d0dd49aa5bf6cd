#!/usr/bin/env bash
# model.svg in a real browser: runs the stage, the parallelogram, the pan-tilt, a shell plate
# and a modal case with --out, opens each model.svg in headless Chromium (Debian's `chromium`),
# screenshots it at the SVG's own size and checks the screenshot (scripts/model_svg_check.py:
# not blank, the drawing inside the view, hinge colours = the utilisations of result.json).
#
# Exit 0: passed, or skipped because Chromium cannot be installed here (said on stdout);
# exit 1: a wrong picture. Needs target/release/flexfem (built by `cargo test --release`).
# `--install-only`: just install Chromium if missing (.ci/run does this in the background first).
set -uo pipefail
cd "$(dirname "$0")/.."
bin=target/release/flexfem
if [ "${1:-}" != "--install-only" ]; then
    [ -x "$bin" ] || { echo "model_svg_test: $bin missing (run cargo build --release first)"; exit 1; }
    command -v python3 >/dev/null || { echo "model_svg_test: SKIPPED (no python3)"; exit 0; }
fi

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
        echo "model_svg_test: installing Debian's chromium"
        { apt-get install -y -q chromium || { apt-get update -q && apt-get install -y -q chromium; }; } \
            >/tmp/model_svg_chromium_install.log 2>&1
        browser=$(command -v chromium || true)
    fi
fi
if [ "${1:-}" = "--install-only" ]; then
    # .ci/run starts this in the background while Rust builds (the download is the slow part).
    [ -n "$browser" ] && echo "model_svg_test: chromium ready ($browser)"
    exit 0
fi
if [ -z "$browser" ]; then
    echo "model_svg_test: SKIPPED (Chromium cannot be installed here; see /tmp/model_svg_chromium_install.log)"
    exit 0
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rc=0
for case in ruiz2019_stage parallelogram_guide pantilt_8r static_plate_shell pantilt_8r_modal; do
    out="$tmp/$case"
    if ! "$bin" run "cases/$case.json" --out "$out" >/dev/null; then
        echo "model_svg_test: flexfem run cases/$case.json failed"
        rc=1
        continue
    fi
    size=$(sed -n 's/^<svg [^>]*width="\([0-9]*\)" height="\([0-9]*\)".*/\1,\2/p' "$out/model.svg" | head -1)
    timeout 60 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --hide-scrollbars --force-device-scale-factor=1 --user-data-dir="$tmp/profile" \
        --window-size="$size" --screenshot="$tmp/$case.png" "file://$out/model.svg" \
        >"$tmp/$case.log" 2>&1
    if [ ! -s "$tmp/$case.png" ]; then
        echo "model_svg_test: no screenshot of $case (chromium log follows)"
        tail -5 "$tmp/$case.log"
        rc=1
        continue
    fi
    python3 scripts/model_svg_check.py "$out" "$tmp/$case.png" || rc=1
done
exit $rc
