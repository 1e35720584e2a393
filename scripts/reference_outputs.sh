#!/bin/bash
# Reference outputs of the modaltyre commands on the bundled configs and data, to prove that a
# restructuring changes no figure (issue 17: "outputs byte-identical").
# usage: scripts/reference_outputs.sh BINARY OUTDIR [SRC]
#   SRC: the source tree whose configs/ and tests/data are used (default: the current directory).
#   REF_W: scratch folder for written files (default /tmp/ref17w); the program prints output
#   paths, so compare only runs made with the same REF_W, and give concurrent runs their own.
# Typical use: build the commit before the change into build-ref, then
#   scripts/reference_outputs.sh build-ref/modaltyre /tmp/before && \
#   scripts/reference_outputs.sh build/modaltyre /tmp/after && diff -r /tmp/before /tmp/after
# Wall-clock figures (transient wall_s / real-time factor, sweep wall and rate) are masked.
set -u
BIN=$(readlink -f "$1"); OUT=$(readlink -f "$2"); SRC=$(readlink -f "${3:-.}")
W=${REF_W:-/tmp/ref17w}   # fixed scratch folder (REF_W: give each concurrent run its own): output paths printed by the program are the same per run
rm -rf "$W" "$OUT"; mkdir -p "$W" "$OUT"
cd "$SRC"
mask() { sed -E -e 's/(in )[0-9.]+( s \(real-time factor )[0-9.]+/\1X\2X/' \
  -e 's/"(wall_s|real_time_factor|cases_per_s)": [0-9.e+-]+/"\1": X/' \
  -e 's/[0-9.]+ s wall, [0-9.]+ cases\/s/X s wall, X cases\/s/'; }
n=0
run() {  # run NAME ARGS...
  local name=$1; shift
  "$BIN" "$@" > "$W/stdout" 2> "$W/stderr"; echo $? > "$OUT/$name.rc"
  mask < "$W/stdout" > "$OUT/$name.out"; mask < "$W/stderr" > "$OUT/$name.err"
  n=$((n+1))
}
keep() { cp "$W/$1" "$OUT/$2"; }  # a written file

C=configs/sf350.yaml; T3=configs/data/sf350_footprint_table3.csv; R=tests/data/rheology
# fit-modes, effects
run fitmodes fit-modes configs/data/sf350_hammer_12pt.csv
run fitmodes_json fit-modes configs/data/sf350_hammer_12pt.csv --json
run effects effects
run effects_json effects --json
# footprint
for cfg in sf350 sf350_fig5 sf350_rigid_belt; do
  run fp_$cfg footprint configs/$cfg.yaml
  run fp_${cfg}_json footprint configs/$cfg.yaml --json
done
run fp_loads footprint $C --load 2131 --load 8321
run fp_fx footprint $C --load 4000 --fx 800 --json
run fp_fx_text footprint $C --load 4000 --load 6000 --fx -500
run fp_plot footprint $C --load 2131 --load 8321 --plot "$W/fp.svg"; keep fp.svg fp_plot.svg
for e in inflation_pressure tread_relaxation dry_friction load_stiffening tread_coupling soil_compliance rolling_speed contact_width belt_flattening; do
  run fp_eff_$e footprint $C --set effects.$e.enabled=true --json
done
run fp_eff_many footprint $C --set effects.dry_friction.enabled=true --set effects.contact_width.enabled=true --set effects.tread_coupling.enabled=true --load 3000 --load 7000
run fp_eff_fx footprint $C --set effects.load_stiffening.enabled=true --load 4000 --fx 600 --json
run fp_bad footprint $C --load -1
# validate
run val validate $C $T3
run val_json validate $C $T3 --json
run val_nocal validate $C $T3 --set 'validation.calibrate=[]' --json
run val_fig5 validate configs/sf350_fig5.yaml $T3
run val_rigid validate configs/sf350_rigid_belt.yaml $T3 --json
run val_eff validate $C $T3 --set effects.load_stiffening.enabled=true --json
run val_eff_text validate $C $T3 --set effects.contact_width.enabled=true
run val_plot validate $C $T3 --plot "$W/val.svg"; keep val.svg val_plot.svg
# sweeps (every bundled sweep file)
for s in table3_loads modulus_load_grid hidden_tread_creep bench_10k; do
  run sw_$s sweep configs/sweeps/$s.yaml --threads 2 --output "$W/$s.csv" --json; keep $s.csv sw_$s.csv
done
run sw_warm sweep configs/sweeps/modulus_load_grid.yaml --threads 2 --warm-start --output "$W/warm.csv"; keep warm.csv sw_warm.csv
run sw_set sweep configs/sweeps/table3_loads.yaml --threads 1 --set effects.dry_friction.enabled=true --set branch=unload --output "$W/set.csv"; keep set.csv sw_set.csv
# validate / discover on sweep output (rows with conditions)
run val_creep validate $C "$W/hidden_tread_creep.csv" --json
run val_creep_text validate $C "$W/hidden_tread_creep.csv"
run val_creep_eff validate $C "$W/hidden_tread_creep.csv" --set effects.tread_relaxation.enabled=true
run disc_t3 discover $C $T3 --json
run disc_t3_text discover $C $T3 --out-config "$W/t3_aug.yaml"; keep t3_aug.yaml disc_t3_aug.yaml
run disc_creep discover $C "$W/hidden_tread_creep.csv" --out-config "$W/creep_aug.yaml" --plot "$W/disc.svg"
keep creep_aug.yaml disc_creep_aug.yaml; keep disc.svg disc_creep.svg
run disc_creep_json discover $C "$W/hidden_tread_creep.csv" --json
run fp_creep_aug footprint "$W/creep_aug.yaml"
# transient scenarios
for s in load-hold free-vibration rolling cleat; do
  run tr_$s transient $C --scenario $s --json --csv "$W/tr_$s.csv"; keep tr_$s.csv tr_$s.csv
done
run tr_hold_text transient $C --scenario load-hold --set contact.unit_length_mm=4 --set transient.load_hold.hold_s=5
run tr_roll_norelax transient $C --scenario rolling --set transient.relaxation=false --set contact.unit_length_mm=2 --csv "$W/tr_nr.csv"; keep tr_nr.csv tr_roll_norelax.csv
run tr_plot transient $C --scenario free-vibration --set contact.unit_length_mm=4 --plot "$W/tr.svg"; keep tr.svg tr_plot.svg
# transient on the 2D config (the 3D default is refused above, with its sentence)
C2=configs/sf350_2d_table3.yaml
for s in load-hold free-vibration rolling cleat; do
  run tr2_$s transient $C2 --scenario $s --set contact.unit_length_mm=2 --json --csv "$W/tr2_$s.csv"; keep tr2_$s.csv tr2_$s.csv
done
# EMA front end and the .tir bridge
python3 examples/ema/synthesise_frfs.py configs/data/sf350_hammer_12pt.csv --noise 0.01 --seed 19 > "$W/frf.csv"
run ema_frf ema "$W/frf.csv" --band 80:350 --json --output "$W/ema_hammer.csv"; keep ema_hammer.csv ema_hammer.csv
run ema_fixed ema tests/data/ema/fixed_columns.unv --json
run tir_cmp tir compare $C tests/data/tir/mfswift62_mm_kN.tir --json
run tir_cmp2 tir compare $C2 tests/data/tir/tyredyn_car205_60R19_mf62.tir
run tir_exp tir export $C --output "$W/sf350.tir"; keep sf350.tir tir_exp.tir
run tir_ftire tir compare $C tests/data/tir/ftire_model.tir
# identify
run id_ld identify load-deflection $R/load_deflection.csv --config $C
run id_ld_json identify load-deflection $R/load_deflection.csv --config $C --json
run id_ld_plot identify load-deflection $R/load_deflection.csv --config $C --plot "$W/ld.svg"; keep ld.svg id_ld.svg
run id_ld_into identify load-deflection $R/load_deflection.csv --into-config $C --out-config "$W/ld_out.yaml" --json; keep ld_out.yaml id_ld_out.yaml
run id_ld_write identify load-deflection $R/load_deflection.csv --config $C --write-config "$W/ld_w.yaml"; keep ld_w.yaml id_ld_w.yaml
run id_ld_norec identify load-deflection $R/load_deflection.csv --r0-mm 295 --write-config "$W/ld_rec.yaml"; keep ld_rec.yaml id_ld_rec.yaml
run id_bf identify b-factors
run id_bf_json identify b-factors --samples 6 --sampling deflection --json
run id_bf_angle identify b-factors --samples 9 --sampling angle --intercept
run id_bf_write identify b-factors --write-config "$W/bf.yaml"; keep bf.yaml id_bf.yaml
run id_bf_into identify b-factors --into-config $C --out-config "$W/bf_out.yaml"
run id_cs identify contact-stress $R/contact_stress.csv --config $C
run id_cs_json identify contact-stress $R/contact_stress.csv --config $C --json --plot "$W/cs.svg"; keep cs.svg id_cs.svg
run id_cs_into identify contact-stress $R/contact_stress.csv --config $C --into-config $C --out-config "$W/cs_out.yaml"; keep cs_out.yaml id_cs_out.yaml
run id_cs_write identify contact-stress $R/contact_stress.csv --config $C --write-config "$W/cs_w.yaml" --json; keep cs_w.yaml id_cs_w.yaml
run id_fv identify free-vibration $R/free_vibration.csv --mass-kg 350 --config $C
run id_fv_static identify free-vibration $R/free_vibration.csv --config $C --mass-kg 350 --section-height-mm 117 --static $R/static_loop.csv --write-config "$W/fv_w.yaml"; keep fv_w.yaml id_fv_w.yaml
run id_fv_into identify free-vibration $R/free_vibration.csv --mass-kg 350 --section-height-mm 117 --static $R/static_loop.csv --into-config $C --out-config "$W/fv_out.yaml" --json --plot "$W/fv.svg"
keep fv_out.yaml id_fv_out.yaml; keep fv.svg id_fv.svg
run fp_fv_out footprint "$W/fv_out.yaml" --load 4000
run id_fv_nostatic_write identify free-vibration $R/free_vibration.csv --mass-kg 350 --config $C --write-config "$W/fv_ns.yaml"; keep fv_ns.yaml id_fv_ns.yaml
run id_soil identify soil-rolling $R/soil_rolling.csv --r0-mm 500 --tread-width-mm 300 --json
run id_soil_into identify soil-rolling $R/soil_rolling.csv --r0-mm 500 --tread-width-mm 300 --into-config $C --out-config "$W/soil_out.yaml"; keep soil_out.yaml id_soil_out.yaml
run val_soil_out validate "$W/soil_out.yaml" $T3
run id_soil_plot identify soil-rolling $R/soil_rolling.csv --r0-mm 500 --tread-width-mm 300 --plot "$W/soil.svg"; keep soil.svg id_soil.svg
# input errors (messages are part of the output)
run err_unknown foo
run err_set footprint $C --set tread.modolus_MPa=3
run err_scen transient $C --scenario jump
run err_meas validate $C tests/data/rheology/soil_rolling.csv
echo "$n commands -> $OUT"
