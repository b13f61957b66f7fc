# Sourced by the desktop key tests of the fly-camera exercises (cascades.sh, bulb.sh), after they
# set app (penumbra-desktop), cli (penumbra), out (the output folder), exercise (its name) and
# scene (the glTF file `penumbra render` draws the same frame from).
shot() {  # shot NAME KEYS: the exercise from its start, KEYS pressed, the 8th frame's screenshot
  local name=$1 keys=$2
  rm -f "$out/$name.png"
  if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise "$exercise" --frames 8 --keys "$keys" --print-title \
       --screenshot "$out/$name.png" >"$out/$name.log" 2>&1; then
    echo "desktop $exercise $name: penumbra-desktop failed:"; cat "$out/$name.log"; exit 1
  fi
  grep -q "^8 frames" "$out/$name.log" || { echo "desktop $exercise $name: did not render 8 frames:"; cat "$out/$name.log"; exit 1; }
}
cli() {  # cli NAME [render options...]: the same frame headless
  local name=$1
  shift
  "$cli" render --scene "$scene" --size 512x512 --out "$out/$name-cli.png" "$@" >/dev/null
}
title_has() {  # title_has NAME TEXT: the last title printed holds TEXT
  grep "^title: " "$out/$1.log" | tail -1 | grep -qF -- "$2" || {
    echo "desktop $exercise $1: the title lacks '$2':"; grep "^title: " "$out/$1.log" | tail -1; exit 1; }
}
