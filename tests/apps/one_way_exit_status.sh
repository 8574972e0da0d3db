#!/bin/sh
# The real executable on bad recorded interface files: one line on stderr naming the scene
# and the key, exit status 2, before any step. Usage: one_way_exit_status.sh FSI SCENE
fsi=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$fsi" run "$scene" --out "$dir/short" --threads 1 --set time.end=0.002 --set output.interval=0.002 \
  >/dev/null 2>&1 || exit 1
expect_2() { # KEY, then the fsi arguments
  key=$1
  shift
  "$fsi" run "$scene" --out "$dir/never" "$@" 2>"$dir/err"
  status=$?
  if [ $status -ne 2 ] || [ "$(wc -l <"$dir/err")" -ne 1 ] ||
    ! grep -q "^$scene[:].*: $key: " "$dir/err" || [ -e "$dir/never" ]; then
    echo "expected one line '$scene...: $key: ...' and exit 2, got $status:"
    cat "$dir/err"
    exit 1
  fi
}
expect_2 coupling.motion --set coupling.scheme=one_way_fluid --set coupling.motion="$dir/none.h5"
expect_2 coupling.loads --set coupling.scheme=one_way_structure --set coupling.loads="$scene"
expect_2 coupling.motion --set coupling.scheme=one_way_fluid \
  --set coupling.motion="$dir/short/fields.h5"
expect_2 coupling.loads --set coupling.scheme=one_way_structure \
  --set coupling.loads="$dir/short/interface.h5"
expect_2 coupling.loads --set coupling.scheme=one_way_structure \
  --set coupling.loads="$dir/short/interface.h5" --set time.end=0.002 \
  --set "structures[0].mesh.elements_y=6"
echo "all bad files: exit 2"
