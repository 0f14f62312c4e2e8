#!/usr/bin/env bash
# All or nothing per frame (issue 51 items 4 and 7). A frame's outputs
# (-o, --film, --water; -o, --far) are staged together and replaced
# together: when one of them cannot be written, none of that frame's files
# is replaced. The failure is made by the file size limit (`ulimit -f 1`:
# the .tx wetness map, 1.9 KB, fails with EFBIG where a full disk gives
# ENOSPC; the 158-byte PNGs fit), as in cli_outputs. Replacement is seen by
# inode: a staged file is renamed into place, so a replaced file has a new
# inode. Before: --film and --water were replaced, -o was not. Then the
# temporaries a killed run leaves (".<name>.tmp<pid>.<n>" of a process that
# is gone) are removed by the next run of the same outputs, and no others.
# SIGKILL between two renames of one frame cannot be waited for: the set's
# renames are journalled first, and the next run of the same outputs
# completes a dead run's journal (the frame becomes the killed run's, whole)
# even when that run then fails; a journal naming a file that is not a
# temporary of its output moves nothing. Frame patterns in a folder name
# get each frame's folder swept.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/frame_publication"
rm -rf "$D" && mkdir -p "$D"
cd "$D" || exit 1
printf 'v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >q.obj
RAIN=(bake rain q.obj --width 64 --height 64 --fps 0.2 --frames 1-2 -o 'w%04d.tx' --film 'f%04d.png' --water 'h%04d.png')
inodes() { stat -c '%i' "w000$1.tx" "f000$1.png" "h000$1.png" | tr '\n' ' '; }

expect_exit 0 "first run" -- "$SOAK" "${RAIN[@]}"
b1=$(inodes 1) b2=$(inodes 2)
expect_exit 1 "second run, the wetness map over the file size limit" -- \
  bash -c 'ulimit -f 1; trap "" XFSZ; exec "$0" "$@"' "$SOAK" "${RAIN[@]}" --seed 5
grep -q "w0001.tx" "$SOAK_TMP/last.err" && ok "the failure names the file" || bad "message: $(cat "$SOAK_TMP/last.err")"
for f in 1 2; do
  before=$([ $f = 1 ] && echo "$b1" || echo "$b2")
  after=$(inodes $f)
  changed=0
  for k in 1 2 3; do [ "$(echo "$before" | cut -d' ' -f$k)" != "$(echo "$after" | cut -d' ' -f$k)" ] && changed=$((changed + 1)); done
  { [ $changed = 0 ] || [ $changed = 3 ]; } && ok "frame $f: $changed of 3 outputs replaced (all or none)" \
    || bad "frame $f: $changed of 3 outputs replaced: one frame mixes two runs"
done
[ -z "$(ls -A | grep '\.tmp')" ] && ok "no temporary left" || bad "temporaries left: $(ls -A | grep '\.tmp')"

# Stale temporaries: a gone process's, of a planned output, are removed;
# another name's and a live process's stay.
dead=$(sh -c 'echo $$')
touch ".w0001.tx.tmp$dead.0" ".h0002.png.tmp$dead.2" ".other.exr.tmp$dead.0" ".w0002.tx.tmp$$.0"
expect_exit 0 "a rerun of the same outputs" -- "$SOAK" "${RAIN[@]}"
[ ! -e ".w0001.tx.tmp$dead.0" ] && [ ! -e ".h0002.png.tmp$dead.2" ] && ok "the dead run's temporaries of -o and --water removed" \
  || bad "stale temporaries kept: $(ls -A | grep tmp | tr '\n' ' ')"
[ -e ".other.exr.tmp$dead.0" ] && ok "another output's temporary kept" || bad "removed a temporary not of these outputs"
[ -e ".w0002.tx.tmp$$.0" ] && ok "a live process's temporary kept" || bad "removed a live process's temporary"
grep -q "left by an interrupted run" "$SOAK_TMP/last.err" && ok "the removal is reported" || bad "removal not reported"

[ -z "$(ls -A | grep '\.journal')" ] && ok "no journal left by finished runs" || bad "journal left: $(ls -A | grep journal)"

# A run killed after renaming w0001.tx, before f0001.png and h0001.png: its
# finished temporaries and journal are on disk (the bytes stand for frames).
printf new-w >w0001.tx
printf new-f >".f0001.png.tmp$dead.1"
printf new-h >".h0001.png.tmp$dead.2"
printf keep >victim.txt
printf 'soak-staged-journal 1\0%s\0%s\0%s\0%s\0%s\0%s\0%s\0%s\0' \
  "$D/.w0001.tx.tmp$dead.0" "$D/w0001.tx" "$D/.f0001.png.tmp$dead.1" "$D/f0001.png" \
  "$D/.h0001.png.tmp$dead.2" "$D/h0001.png" "$D/victim.txt" "$D/w0002.tx" >".w0001.tx.journal$dead"
expect_exit 1 "a rerun of the same outputs that fails (mesh gone)" -- \
  "$SOAK" bake rain gone.obj --width 64 --height 64 --fps 0.2 --frames 1-2 -o 'w%04d.tx' --film 'f%04d.png' --water 'h%04d.png'
[ "$(cat w0001.tx f0001.png h0001.png)" = "new-wnew-fnew-h" ] && ok "the killed run's frame 1 completed: all three from it" \
  || bad "frame 1 mixes runs: $(head -c 20 f0001.png) $(head -c 20 h0001.png)"
[ ! -e ".w0001.tx.journal$dead" ] && ok "the journal removed" || bad "journal kept"
[ "$(cat victim.txt)" = keep ] && [ -e victim.txt ] && ok "a journal entry that is not a temporary of its output moves nothing" \
  || bad "victim.txt moved by a journal"
grep -q "completed 2 renames" "$SOAK_TMP/last.err" && ok "the completion is reported" \
  || bad "not reported: $(head -c 300 "$SOAK_TMP/last.err")"

# A frame pattern in the folder's name: each frame's folder is swept.
mkdir -p d01 d02
touch "d02/.w.exr.tmp$dead.0"
expect_exit 0 "frames into per-frame folders" -- "$SOAK" bake rain q.obj --width 16 --height 16 --fps 0.2 --frames 1-2 \
  -o 'd%02d/w.exr'
[ ! -e "d02/.w.exr.tmp$dead.0" ] && ok "a dead run's temporary in frame 2's folder removed" || bad "kept: d02/.w.exr.tmp$dead.0"
finish
