#!/usr/bin/env bash
# OpenImageIO is loaded only when a file needs it (issue 25): the CLI does
# not link it, `flatten`, `--help` and PNG renders never load it, the other
# formats load its module and work, and without the module they fail with a
# message and status 1. Whether a library is loaded is read from the dynamic
# loader's own trace (LD_DEBUG=libs); that the trace shows a load is checked
# too, on a render that needs the module, so these checks can fail.
# Usage: io_cli_test.sh PATH/TO/casteljau PATH/TO/libcasteljau_oiio.so DATA_DIR
set -u
bin="$1"; module="$2"; data="$3"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/harness.sh"

# Not linked, directly or through another library.
if readelf -d "$bin" | grep -q 'NEEDED.*OpenImageIO'; then fail "linked: $(readelf -d "$bin" | grep OpenImageIO)"; else pass; fi
if ldd "$bin" | grep -q OpenImageIO; then fail "ldd: $(ldd "$bin" | grep OpenImageIO)"; else pass; fi

# The libraries the loader opens for a command (its LD_DEBUG=libs trace).
loads() { LD_DEBUG=libs "$bin" "$@" 2>&1 >/dev/null | grep -E 'calling init: ' ; }
never_loads_oiio() {
    local name="$1"; shift
    local trace; trace="$(loads "$@")"
    [[ -n "$trace" ]] || { fail "$name: no loader trace (LD_DEBUG unsupported?)"; return; }
    if grep -Eq 'OpenImageIO|casteljau_oiio' <<<"$trace"; then fail "$name loads OpenImageIO: $(grep -E 'OpenImageIO|casteljau_oiio' <<<"$trace" | head -2)"; else pass; fi
}
never_loads_oiio flatten flatten --path 'M0 0 C 10 10 20 0 30 10'
never_loads_oiio help --help
never_loads_oiio render_png render "$data/ok.svg" -o "$tmp/a.png"
never_loads_oiio render_jpg render "$data/ok.svg" -o "$tmp/a.jpg"
# A PNG <image> is decoded by libpng, not OpenImageIO.
echo "<svg xmlns='http://www.w3.org/2000/svg' width='40' height='30'><image width='40' height='30' href='data:image/png;base64,$(base64 -w0 "$tmp/a.png")'/></svg>" > "$tmp/image.svg"
never_loads_oiio render_png_image render "$tmp/image.svg" -o "$tmp/image.png"
[[ "$(LD_DEBUG= "$bin" render "$tmp/image.svg" -o "$tmp/image.png" 2>&1)" == "" ]] && pass || fail "render_png_image: warnings"
# The control: a format only OpenImageIO writes shows its loading in the trace.
if grep -q 'OpenImageIO' <<<"$(loads render "$data/ok.svg" -o "$tmp/a.exr")"; then pass; else fail "exr: the trace does not show OpenImageIO loading"; fi

# Each format written (EXR and TIFF through the module, found in the build
# tree and where the variable points), and JPEG read back as a texture.
for ext in exr tif jpg; do
    expect "write_$ext" 0 '' render "$data/ok.svg" -o "$tmp/ok.$ext"
    [[ -s "$tmp/ok.$ext" ]] && pass || fail "write_$ext: no file"
done
if CASTELJAU_OIIO_MODULE="$module" "$bin" render "$data/ok.svg" -o "$tmp/env.tif" && [[ -s "$tmp/env.tif" ]]; then pass; else fail "CASTELJAU_OIIO_MODULE=$module: no file"; fi
expect texture 0 '' patch "$data/../../../examples/patch/wave.bpt" -o "$tmp/p.png" --texture "$tmp/ok.jpg"
expect texture_tif 0 '' patch "$data/../../../examples/patch/wave.bpt" -o "$tmp/p.png" --texture "$tmp/ok.tif"
never_loads_oiio patch_jpeg_texture patch "$data/../../../examples/patch/wave.bpt" -o "$tmp/p.png" --texture "$tmp/ok.jpg"
# A JPEG or WebP <image> is decoded by libjpeg or libwebp, not OpenImageIO
# (the WebP written by oiiotool, which setup.sh installs).
echo "<svg xmlns='http://www.w3.org/2000/svg' width='40' height='30'><image width='40' height='30' href='ok.jpg'/></svg>" > "$tmp/jpeg_image.svg"
never_loads_oiio render_jpeg_image render "$tmp/jpeg_image.svg" -o "$tmp/jpeg_image.png"
oiiotool "$tmp/a.png" -o "$tmp/ok.webp"
echo "<svg xmlns='http://www.w3.org/2000/svg' width='40' height='30'><image width='40' height='30' href='ok.webp'/></svg>" > "$tmp/webp_image.svg"
never_loads_oiio render_webp_image render "$tmp/webp_image.svg" -o "$tmp/webp_image.png"
for kind in jpeg webp; do
    [[ "$(LD_DEBUG= "$bin" render "$tmp/${kind}_image.svg" -o "$tmp/${kind}_image.png" 2>&1)" == "" && -s "$tmp/${kind}_image.png" ]] && pass || fail "render_${kind}_image: warnings or no file"
done

# Without the module: the message says what needed it and where it was
# looked for; status 1; no file, and an existing one untouched.
missing=/nonexistent/libcasteljau_oiio.so
echo precious > "$tmp/keep.exr"
out="$(CASTELJAU_OIIO_MODULE=$missing "$bin" render "$data/ok.svg" -o "$tmp/keep.exr" 2>&1)"; status=$?
if [[ $status -eq 1 && "$out" == *"writing .exr needs OpenImageIO: module libcasteljau_oiio.so not found (searched $missing"* ]]; then pass; else fail "missing module, exr: exit $status: $out"; fi
[[ "$(cat "$tmp/keep.exr")" == precious ]] && pass || fail "missing module: the existing file changed"
out="$(CASTELJAU_OIIO_MODULE=$missing "$bin" patch "$data/../../../examples/patch/wave.bpt" -o "$tmp/q.png" --texture "$tmp/ok.tif" 2>&1)"; status=$?
if [[ $status -eq 1 && "$out" == *"needs OpenImageIO"* && ! -e "$tmp/q.png" ]]; then pass; else fail "missing module, texture: exit $status: $out"; fi
# PNG and JPEG need no module.
for ext in png jpg; do
    if CASTELJAU_OIIO_MODULE=$missing "$bin" render "$data/ok.svg" -o "$tmp/b.$ext" && [[ -s "$tmp/b.$ext" ]]; then pass; else fail "missing module, $ext: no file"; fi
done
# A file that is not a module: named, with the loader's reason.
echo "not a library" > "$tmp/libfake.so"
out="$(CASTELJAU_OIIO_MODULE=$tmp/libfake.so "$bin" render "$data/ok.svg" -o "$tmp/c.tif" 2>&1)"; status=$?
if [[ $status -eq 1 && "$out" == *"cannot be loaded: $tmp/libfake.so"* ]]; then pass; else fail "not a module: exit $status: $out"; fi

finish "io CLI"
