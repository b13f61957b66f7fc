# Sourced by the desktop tests that look at an exercise's visibility view (soft.sh, volumes.sh),
# after they set app (penumbra-desktop), out (the output folder), exercise (its name) and time
# (the frozen t).
shot() {  # shot NAME [app options...]: the 5th frame's screenshot, in the visibility view
  local name=$1
  shift
  rm -f "$out/$name.png"
  if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise "$exercise" --frames 5 --time "$time" --aov visibility \
       --screenshot "$out/$name.png" "$@" >"$out/$name.log" 2>&1; then
    echo "desktop $exercise $name: penumbra-desktop failed:"; cat "$out/$name.log"; exit 1
  fi
  grep -q "^5 frames" "$out/$name.log" || { echo "desktop $exercise $name: did not render 5 frames:"; cat "$out/$name.log"; exit 1; }
}
