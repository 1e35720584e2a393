#!/bin/bash
# Issue 21's accuracy metrics of the four transient scenarios, by the definitions of
# tests/transient/reference_test.cc (free vibration: hub displacement minus its mean over
# t > 0.8 s, maxima refined by parabolas, linear fits of time and log amplitude over the first 8;
# cleat: largest load_N sample; rolling: the --json final values; load-hold: final sinking).
# usage: scripts/transient_reference_metrics.sh BINARY OUTDIR [--set key=value]...
# e.g. the 0.25 mm reference: ... build/modaltyre /tmp/ref025 --set contact.unit_length_mm=0.25
set -eu
BIN=$1; OUT=$2; shift 2
CONFIG=$(dirname "$0")/../configs/sf350_2d_table3.yaml
mkdir -p "$OUT"
for s in free-vibration rolling cleat load-hold; do
  "$BIN" transient "$CONFIG" --scenario "$s" --csv "$OUT/$s.csv" --json "$@" > "$OUT/$s.json"
done
/usr/bin/python3 - "$OUT" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
def rows(p):
    with open(p) as f:
        return [{k: float(v) for k, v in r.items()}
                for r in csv.DictReader(l for l in f if not l.startswith('#'))]
def slope(y):
    n = len(y); sx = sum(range(n)); sy = sum(y)
    sxx = sum(i * i for i in range(n)); sxy = sum(i * v for i, v in enumerate(y))
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)
s = rows(f'{d}/free-vibration.csv')
z = [r['hub_displacement_mm'] for r in s]; t = [r['t_s'] for r in s]
late = [v for v, tt in zip(z, t) if tt > 0.8]
mean = sum(late) / len(late)
times, logs = [], []
for i in range(1, len(s) - 1):
    if len(times) >= 8: break
    a, b, c = z[i - 1] - mean, z[i] - mean, z[i + 1] - mean
    if not (b > a and b >= c and b > 0): continue
    den = a - 2 * b + c; off = 0.5 * (a - c) / den if den != 0 else 0
    times.append(t[i] + off * (t[1] - t[0])); logs.append(math.log(b - 0.25 * (a - c) * off))
roll = json.load(open(f'{d}/rolling.json'))['final']
out = {'period_s': slope(times), 'log_decrement': -slope(logs),
       'rolling_resistance_N': roll['rolling_resistance_N'],
       'rolling_contact_length_mm': roll['contact_length_mm'],
       'cleat_peak_load_N': max(r['load_N'] for r in rows(f'{d}/cleat.csv')),
       'hold_final_sinking_mm': rows(f'{d}/load-hold.csv')[-1]['sinking_mm']}
for sc in ['free-vibration', 'rolling', 'cleat', 'load-hold']:
    out[sc + '_steps'] = json.load(open(f'{d}/{sc}.json'))['steps']
print(json.dumps(out, indent=1))
PY
