#!/bin/bash
# lint kinds before / after casteljau / after fontTools, and times, for the four fonts
C=${CASTELJAU:-target/release/casteljau}
PY=${PYTHON:-python3}  # with fontTools and skia-pathops
OUT=${OUT:-/tmp}
for f in /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf /usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf /usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf /usr/share/fonts/opentype/urw-base35/NimbusSans-Regular.otf; do
  b=$(basename $f)
  t0=$(date +%s.%N); $C remove-overlaps $f -o $OUT/cj-$b -q; t1=$(date +%s.%N)
  $PY -c "
import sys,time
from fontTools.ttLib import TTFont
from fontTools.ttLib.removeOverlaps import removeOverlaps
t=time.perf_counter(); f=TTFont(sys.argv[1]); removeOverlaps(f, ignoreErrors=True); f.save(sys.argv[2]); print('fonttools_s', round(time.perf_counter()-t,2))" $f $OUT/ft-$b 2>/dev/null
  echo "$b casteljau_s $(echo "$t1 - $t0" | bc)"
  for v in $f $OUT/cj-$b $OUT/ft-$b; do echo "  $(basename $(dirname $v))/$(basename $v): $($C lint $v -q 2>/dev/null | tail -1)"; done
done
