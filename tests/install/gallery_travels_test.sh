#!/bin/sh
# A gallery that travels (issue 40): `cmake --install` puts the program and the scenes it ships
# into a prefix; that program alone renders a gallery figure from a folder outside both trees;
# the command printed under the figure, run as printed from the gallery folder (moved elsewhere
# first), makes the same image again.
# Usage: gallery_travels_test.sh BUILD_DIR
set -eu
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/share/hikari/scenes/models/teapot.obj"
mkdir "$work/elsewhere"
cd "$work/elsewhere"
# Fig 4.1a draws the default model: the installed copy, copied again into the gallery.
"$work/prefix/bin/hikari" gallery -o g --only 4.1a --width 64 2>/dev/null
cmp g/scenes/teapot.obj "$work/prefix/share/hikari/scenes/models/teapot.obj"
mv g "$work/moved"
cd "$work/moved"
commands=$(sed -n 's/.*<code>\(hikari render[^<]*\)<\/code>.*/\1/p' index.html | sed 's/&quot;/"/g; s/&lt;/</g; s/&gt;/>/g; s/&amp;/\&/g')
test -n "$commands"
images=$(echo "$commands" | sed 's/.* -o \([^ ]*\).*/\1/')
for image in $images; do mv "$image" "$image.gallery"; done
echo "$commands" | PATH="$work/prefix/bin:$PATH" sh -e
for image in $images; do cmp "$image" "$image.gallery"; done
echo "gallery travels: $(echo "$images" | wc -w) image(s) remade from the moved folder"
