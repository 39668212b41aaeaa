#!/usr/bin/env python3
"""Run the loop on the DEVELOPMENT scenarios of gen_dev.py (issue 50; dev data,
not held out) and score them as the hidden-set study does: detected = the first
step names a truth alias AND final held-out RMS <= 2 x the true noise sd; a null
set is a false alarm when the loop adds any step naming an extra column of the
data (base-model terms on pin/pressure/speed/direction are reported apart).
Usage: run_dev.py DRAWBEND_BINARY WORKDIR [seeds=2]"""
import json, os, subprocess, sys, time
here = os.path.dirname(os.path.abspath(__file__))
binary, work = sys.argv[1], sys.argv[2]
seeds = int(sys.argv[3]) if len(sys.argv) > 3 else 2
os.makedirs(work, exist_ok=True)
scens = ["level_peak", "dir_peak", "one_cell_pin", "one_cell_speed", "coil_pin_nuis", "lot_small", "thickness_bend",
         "sat_exp", "linear", "null", "null_mismatch"]
COLS = {"test_order", "coil", "lot", "thickness_mm", "temperature_C", "tool_temp_C", "lube_g", "humidity_pct",
        "operator", "sliding_distance_mm", "time_s"}
per = {}
for sc in scens:
    for noise in (3.0, 8.0):
        for seed in range(1, seeds + 1):
            csv = os.path.join(work, f"{sc}_{int(noise)}_{seed}.csv")
            truth = json.loads(subprocess.check_output([sys.executable, os.path.join(here, "gen_dev.py"), sc, str(noise),
                                                        str(seed), csv]))
            out = csv[:-4]
            t0 = time.time()
            subprocess.run([binary, "loop", csv, "--out", out, "--threads", "1"], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            dt = time.time() - t0
            s = json.load(open(os.path.join(out, "loop_summary.json")))
            steps = [x["variable"] for x in s["steps"]]
            ratio = s["heldout_rms_N"] / noise
            cls = truth["class"]
            if cls == "null":
                ok = not any(v in COLS for v in steps)
                tag = "ok" if ok else "FALSE ALARM"
            else:
                ok = bool(steps) and steps[0] in truth["aliases"] and ratio <= 2.0
                tag = "detected" if ok else "missed"
            per.setdefault((cls, sc), []).append(ok)
            print(f"{sc:15s} noise {noise:3.0f} seed {seed}: {tag:11s} ratio {ratio:5.2f} {dt:5.1f}s steps {steps}",
                  flush=True)
print("\nper scenario (null: sets without a column step):")
for (cls, sc), v in per.items():
    print(f"  {cls:12s} {sc:15s} {sum(v)}/{len(v)}")
eff = [x for (c, _), v in per.items() if c != "null" for x in v]
nul = [x for (c, _), v in per.items() if c == "null" for x in v]
print(f"detected {sum(eff)}/{len(eff)}; null sets with a false alarm {len(nul) - sum(nul)}/{len(nul)}")
