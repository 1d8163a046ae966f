#!/usr/bin/env bash
# Renders every CS 488 corpus scene (../shared/corpus), every shipped scene (with the
# options its header names) and a preview of each animation with the mjray binary BINARY into
# OUTDIR, and writes the md5 of every image's pixels (decoded by ffmpeg, so neither the PNG
# encoder's settings nor the metadata's paths count) to OUTDIR.md5. Compare two builds (e.g.
# before and after a refactoring that must not change images):
#   scripts/render_all_scenes.sh /tmp/old/mjray /tmp/before && scripts/render_all_scenes.sh build/mjray /tmp/after
#   diff /tmp/before.md5 /tmp/after.md5
set -uo pipefail
bin=$(realpath "$1"); out=$(realpath -m "$2"); mkdir -p "$out"
cd "$(dirname "$0")/.."
shared=${MJRAY_SHARED_DIR:-../shared}
status=0
if [ -d "$shared/corpus/cs488" ]; then
  for s in $(find "$shared/corpus/cs488" -name '*.lua' | sort); do
    grep -q 'gr.render' "$s" || continue  # modules such as readobj.lua
    name=$(echo "${s#"$shared"/corpus/cs488/}" | sed 's#[/.]#_#g')
    mkdir -p "$out/$name"
    "$bin" --quiet --outdir "$out/$name" "$s" 2>"$out/$name.log" || { echo "failed: $s"; status=1; }
  done
fi
for s in scenes/*.lua scenes/features/*.lua; do
  opts=$(grep -m1 -o 'Render: build/mjray[^(]*' "$s" | sed 's#Render: build/mjray##; s#scenes/[^ ]*\.lua##')
  name=$(basename "$s" .lua)
  mkdir -p "$out/$name"
  # shellcheck disable=SC2086
  "$bin" --quiet $opts --outdir "$out/$name" "$s" 2>"$out/$name.log" || { echo "failed: $s"; status=1; }
done
# The animations at a preview size, every eighth of their 96 frames, without their header's
# --video (a movie's bytes depend on the ffmpeg version).
for s in scenes/animation/*.lua; do
  name=$(basename "$s" .lua)
  mkdir -p "$out/$name"
  "$bin" --quiet -s 2 --size 160x90 --frames 1-96:8 --outdir "$out/$name" "$s" 2>"$out/$name.log" || { echo "failed: $s"; status=1; }
done
pixels_md5() { ffmpeg -loglevel error -i "$1" -f rawvideo - | md5sum | sed "s#-\$#$1#"; }
(cd "$out" && for f in $(find . -name '*.png' | sort); do pixels_md5 "$f"; done) > "$out.md5"
echo "$(wc -l < "$out.md5") images; md5s in $out.md5"
exit $status
