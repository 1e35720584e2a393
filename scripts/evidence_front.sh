#!/bin/bash
# Issue 18: every built 3D-patch structure, calibrated as the default is (compliance scale and
# crown radius on sinking and width of Table 3 rows 1 and 6), scored on the two groups of
# Done-when criteria: Table 3's predicted rows 2-5 (sinking, width RMS) and the real-tyre length
# law (length exponent over 2131-8321 N, 2a/R0 RMS against the TNO MF-Tool law). Writes
# OUTDIR/evidence_front.csv and draws OUTDIR/evidence_front.png (gnuplot). About 75 s on
# 2 cores; --plot-only redraws the figure from an existing CSV.
# usage: scripts/evidence_front.sh BUILD_DIR OUTDIR [--plot-only]
set -euo pipefail
BUILD=$1
OUT=$2
PLOT_ONLY=${3:-}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
STUDY=$BUILD/bench/footprint3d_study
CONFIG=$ROOT/configs/sf350.yaml
TABLE3=$ROOT/configs/data/sf350_footprint_table3.csv
mkdir -p "$OUT"
CSV=$OUT/evidence_front.csv

POWER="footprint_3d.crown.shape=power footprint_3d.crown.reference_half_width_mm=60"
BELT="footprint_3d.lateral_belt.supports=free footprint_3d.lateral_belt.bending_stiffness_Nm=0.27"
BELT="$BELT footprint_3d.crown.radius_mm=300" # start of the calibration off the saturated width
SIDE="footprint_3d.sidewall.meridian_chord_mm=117"

# family|label|settings (space-separated key=value; none = the default as it is)
VARIANTS=(
  "default|rigid belt, circular crown (default)|"
  "carcass|measured orders only|modal.extend_orders=false"
  "carcass|extension s2 = 0|modal.extension_bending_s2_rad2_s2=0"
  "carcass|extension s2 = 300|modal.extension_bending_s2_rad2_s2=300"
  "carcass|extension s2 = 1000|modal.extension_bending_s2_rad2_s2=1000"
  "tread|E = 4.5 MPa|tread.modulus_MPa=4.5"
  "tread|E = 6 MPa|tread.modulus_MPa=6"
  "tread|E = 8 MPa|tread.modulus_MPa=8"
  "crown|power n = 4|$POWER footprint_3d.crown.exponent=4"
  "crown|power n = 3|$POWER footprint_3d.crown.exponent=3"
  "crown|power n = 1.5|$POWER footprint_3d.crown.exponent=1.5"
  "crown|power n = 1.2|$POWER footprint_3d.crown.exponent=1.2"
  "pneumatic|beta = 0.1|modal.pneumatic_share=0.1"
  "pneumatic|beta = 0.25|modal.pneumatic_share=0.25"
  "pneumatic|beta = 0.5|modal.pneumatic_share=0.5"
  "sidewall|c0/L = 0.80|$SIDE footprint_3d.sidewall.meridian_length_mm=146.25"
  "sidewall|c0/L = 0.85|$SIDE footprint_3d.sidewall.meridian_length_mm=137.65"
  "sidewall|c0/L = 0.85, power n = 1.5|$SIDE footprint_3d.sidewall.meridian_length_mm=137.65 $POWER footprint_3d.crown.exponent=1.5"
  "belt|k = 56 MPa/m, n = 3|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=56 $POWER footprint_3d.crown.exponent=3"
  "belt|k = 56 MPa/m, n = 4|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=56 $POWER footprint_3d.crown.exponent=4"
  "belt|k = 56 MPa/m, n = 6|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=56 $POWER footprint_3d.crown.exponent=6"
  "belt|k = 113 MPa/m, n = 2|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=113 $POWER footprint_3d.crown.exponent=2"
  "belt|k = 113 MPa/m, n = 4|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=113 $POWER footprint_3d.crown.exponent=4"
  "belt|k = 113 MPa/m, n = 6|$BELT footprint_3d.lateral_belt.foundation_MPa_per_m=113 $POWER footprint_3d.crown.exponent=6"
)

if [ "$PLOT_ONLY" != --plot-only ]; then
TMP=$(mktemp "$OUT/.evidence_front.XXXXXX")
trap 'rm -f "$TMP" "$TMP.run"' EXIT
echo "family,variant,sinking_rms_pct,width_rms_pct,length_rms_pct,length_exponent,width_exponent,tno_rms_pct" >"$TMP"
for entry in "${VARIANTS[@]}"; do
  IFS='|' read -r family label settings <<<"$entry"
  args=()
  for kv in $settings; do args+=(--set "$kv"); done
  printf '%-10s %s\n' "$family" "$label" >&2
  "$STUDY" "$CONFIG" "$TABLE3" --rows 1,6 "${args[@]}" \
    --calibrate modal.compliance_scale,footprint_3d.crown.radius_mm \
    --observables sinking_mm,width_mm >"$TMP.run"
  # The study's own summary lines (bench/footprint3d_study.cc).
  awk -v family="$family" -v label="$label" '
    /^RMS over 4 predicted rows:/ { gsub(/,/, ""); s = $7; l = $10; w = $13 }
    /^  length [0-9]/ { le = $2 }
    /^  width  [0-9]/ { we = $2 }
    /^  RMS [0-9.]+ %/ { t = $2 }
    END {
      if (s == "" || le == "" || we == "" || t == "") { print "unparsed study output" > "/dev/stderr"; exit 1 }
      printf "%s,\"%s\",%s,%s,%s,%s,%s,%s\n", family, label, s, w, l, le, we, t
    }' "$TMP.run" >>"$TMP"
done
mv "$TMP" "$CSV"
rm -f "$TMP.run"
fi

gnuplot <<GP
set terminal pngcairo size 1200,520 font ",10"
set output "$OUT/evidence_front.png"
set datafile separator ","
set key box opaque font ",9"
FAMILIES = "default carcass tread crown pneumatic sidewall belt"
set multiplot layout 1,2
set title "Table 3 (rows 2-5) against the real-tyre length law\n(filled: Table 3 sinking RMS <= 5 %)"
set xlabel "Table 3 width RMS, rows 2-5 [%]"
set ylabel "2a/R0 RMS against the TNO MF-Tool law [%]"
set xrange [0:14]; set yrange [0:32]
set key top right
set object 1 rect from 0,0 to 7,6 fc rgb "#d8f0d8" fs solid 0.6 noborder behind
set label 1 "width and length-law targets" at 0.3,7 font ",9"
set label 2 "c0/L 0.85 + n 1.5" at 3.2,2.2 font ",8"
set arrow 2 from 5.3,2.6 to 6.65,5.5 lc rgb "#606060"
plot for [i=1:words(FAMILIES)] "$CSV" \
       using (strcol(1) eq word(FAMILIES, i) && \$3 <= 5 ? \$4 : NaN):8 \
       with points pt 7 ps 1.3 lc i title word(FAMILIES, i), \
     for [i=1:words(FAMILIES)] "$CSV" \
       using (strcol(1) eq word(FAMILIES, i) && \$3 > 5 ? \$4 : NaN):8 \
       with points pt 6 ps 1.3 lw 2 lc i notitle
unset object 1; unset label 1; unset label 2; unset arrow 2
set title "Where the area growth goes: length against width exponent (2131-8321 N)"
set xlabel "width exponent"
set ylabel "length exponent"
set xrange [0:0.32]; set yrange [0.25:0.75]
set key top left
set object 2 rect from 0.14,0.55 to 0.27,0.67 fc rgb "#d8e4f8" fs solid 0.6 noborder behind
set label 3 "real tyres" at 0.2,0.66 font ",9"
set arrow 1 from 0,0.45 to 0.32,0.45 nohead dt 2 lc rgb "#808080"
set label 4 "band 0.45-0.70" at 0.23,0.44 font ",8"
set label 5 "Table 3" at 0.266,0.301 point pt 3 ps 2.5 lw 2 offset -5,-1 font ",9"
plot for [i=1:words(FAMILIES)] "$CSV" using (strcol(1) eq word(FAMILIES, i) ? \$7 : NaN):6 \
       with points pt 7 ps 1.3 lc i title word(FAMILIES, i)
unset multiplot
GP
echo "wrote $CSV and $OUT/evidence_front.png" >&2
