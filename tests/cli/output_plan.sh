#!/usr/bin/env bash
# One output plan per command (issue 51 item 1): every frame of every output
# (-o, --far, --film, --water, --exposure patterns) is resolved and compared
# with the others and with every input before any work. Each row below was
# accepted with exit 0 before (one output silently overwritten by another,
# or every frame sent to one file); each must now exit 2 naming both options
# and the frame, and write nothing. Reruns of the same outputs stay accepted.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/output_plan"
rm -rf "$D" && mkdir -p "$D/d0" "$D/d1" "$D/d2"
cd "$D" || exit 1
printf 'v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >q.obj
RIP=(bake ripples --width 16)
RAIN=(bake rain q.obj --width 16 --height 16)

# refused WANT1 WANT2 -- command...: exit 2, stderr naming WANT1 and WANT2,
# and no new file in the folder.
refused() {
  local w1=$1 w2=$2
  shift 3
  local before after
  before=$(ls -A | sort)
  expect_exit 2 "$*" -- "$SOAK" "$@"
  after=$(ls -A | sort)
  grep -qF -- "$w1" "$SOAK_TMP/last.err" && grep -qF -- "$w2" "$SOAK_TMP/last.err" \
    && ok "message names '$w1' and '$w2'" || bad "message lacks '$w1'/'$w2': $(cat "$SOAK_TMP/last.err")"
  [ "$before" = "$after" ] && ok "nothing written" || bad "files appeared: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
}

refused "-o frame 1000" "--water frame 1000" -- "${RAIN[@]}" --frames 999-1000 --fps 100 -o 'w.%d.exr' --water 'w.%04d.exr'
refused "-o 'a.exr'" "--far 'a.exr'" -- "${RIP[@]}" -o a.exr --far a.exr
refused "-o frame 0" "--far frame 0" -- "${RIP[@]}" --frames 0-1 -o 'q.%d.exr' --far './q.%d.exr'
refused "--water frame 0" "--film frame 0" -- "${RAIN[@]}" --frames 0-1 -o 'y%d.exr' --film 'z%d.exr' --water 'z%d.exr'
refused "-o frame 10" "--far frame 0" -- "${RIP[@]}" --frames 0-20 -o 'r%d.exr' --far 'r1%d.exr'
refused "-o frame 2" "--exposure 'e2.exr'" -- "${RAIN[@]}" --frames 0-3 -o 'e%d.exr' --exposure e2.exr
refused "-o frame 0" "-o frame 1" -- "${RIP[@]}" --frames 0-1 -o 'd%d/../one.exr'
refused "--far frame 1" "--far frame 2" -- "${RIP[@]}" --frames 1-2 -o 'k%d.exr' --far 'd%d/../kf.exr'
touch target.exr && ln -s target.exr l1.exr && ln -s target.exr l2.exr
refused "-o frame 1" "-o frame 2" -- "${RIP[@]}" --frames 1-2 -o 'l%d.exr'
ln -s d1 dl
refused "-o frame 1" "--far frame 1" -- "${RIP[@]}" --frames 1-1 -o 'd1/x%d.exr' --far 'dl/x%d.exr'
# Reruns of the same outputs (they exist now) are accepted.
expect_exit 0 "first run of -o and --far" -- "$SOAK" "${RIP[@]}" --frames 0-1 -o 'ok.%d.exr' --far 'okf.%d.exr'
expect_exit 0 "rerun over its own outputs" -- "$SOAK" "${RIP[@]}" --frames 0-1 -o 'ok.%d.exr' --far 'okf.%d.exr'
finish
