#!/usr/bin/env bash
# FreeType, HarfBuzz, fontconfig and FriBidi are opened only when a file has
# text (issue 25; text/detail/text_libs.h): the CLI does not link them,
# `--help`, `flatten` and a render without text never load them, a render
# with text does (the control, so that these checks can fail), and where one
# cannot be loaded the text is left out with a warning that says why, the
# rest drawn, status 0. Loads are read from the loader's trace (LD_DEBUG=libs).
# Usage: text_libs_cli_test.sh PATH/TO/casteljau EXAMPLES_DIR DATA_DIR
set -u
bin="$1"; examples="$2"; data="$3"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/harness.sh"
libs='lib(freetype|harfbuzz|fontconfig|fribidi)\.so'

if readelf -d "$bin" | grep -Eq "NEEDED.*$libs"; then fail "linked: $(readelf -d "$bin" | grep -E "$libs")"; else pass; fi
if ldd "$bin" | grep -Eq "$libs"; then fail "ldd: $(ldd "$bin" | grep -E "$libs")"; else pass; fi

loads() { LD_DEBUG=libs "$bin" "$@" 2>&1 >/dev/null | grep -E 'calling init: ' ; }
never_loads() {
    local name="$1"; shift
    local trace; trace="$(loads "$@")"
    [[ -n "$trace" ]] || { fail "$name: no loader trace (LD_DEBUG unsupported?)"; return; }
    if grep -Eq "$libs" <<<"$trace"; then fail "$name loads: $(grep -E "$libs" <<<"$trace" | head -2)"; else pass; fi
}
never_loads help --help
never_loads flatten flatten --path 'M0 0 C 10 10 20 0 30 10'
never_loads render_shapes render "$data/ok.svg" -o "$tmp/shapes.png"
trace="$(loads render "$examples/svg/text.svg" -o "$tmp/text.png")"
for lib in freetype harfbuzz fontconfig fribidi; do
    if grep -q "lib$lib\.so" <<<"$trace"; then pass; else fail "text: lib$lib not in the trace"; fi
done

# A HarfBuzz that does not load (not an ELF file, found first on the path):
# the text is left out, one warning names the library, the rest is drawn.
mkdir "$tmp/broken" && echo "not a library" > "$tmp/broken/libharfbuzz.so.0"
out="$(LD_LIBRARY_PATH="$tmp/broken" "$bin" render "$examples/svg/text.svg" -o "$tmp/no_text.png" 2>&1)"; status=$?
if [[ $status -eq 0 && "$out" == *"no font draws some of this text ("*"libharfbuzz.so.0"* ]]; then pass; else fail "broken HarfBuzz: exit $status: $(head -3 <<<"$out")"; fi
[[ -s "$tmp/no_text.png" ]] && pass || fail "broken HarfBuzz: no file"
cmp -s "$tmp/text.png" "$tmp/no_text.png" && fail "broken HarfBuzz: the text was drawn anyway" || pass

finish "text libraries CLI"
