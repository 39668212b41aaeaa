#!/usr/bin/env python3
"""Chapter 7's demonstration 3 through the command line, to compare two builds
of the loop on the same data (issue 50): the same sets (drawbend synth with
chapter 7's seeds: 1000 + 17 k + noise (+ 500 for null sets), noise 2, 5,
10 N, 5 seeds per effect, 10 null sets per noise level, analytic stand-in maps
unless --maps) and the same scoring (detected: the first step names a truth
alias and the final held-out RMS <= 2 x noise; false alarm: a null set with any
step).  Usage: run_ch7_synth.py DRAWBEND WORKDIR [MAPS_DIR]"""
import json, os, subprocess, sys
binary, work = sys.argv[1], sys.argv[2]
maps = ["--maps", sys.argv[3]] if len(sys.argv) > 3 else []
effects = ["none", "depletion", "pin_surface", "speed", "drift", "direction", "pressure", "curvature", "batch",
           "temperature"]
os.makedirs(work, exist_ok=True)
per, det, eff_n, fa, null_n = {}, 0, 0, 0, 0
for noise in (2, 5, 10):
    for e in effects:
        null = e == "none"
        for k in range(10 if null else 5):
            seed = 1000 + 17 * k + noise + (500 if null else 0)
            out = os.path.join(work, f"{e}_{noise}_{seed}")
            subprocess.run([binary, "synth", "--effect", e, "--noise", str(noise), "--seed", str(seed), "--out", out]
                           + maps, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            subprocess.run([binary, "loop", out + "/data.csv", "--out", out + "/loop", "--figures", "", "--threads",
                            "1"] + maps, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            truth = json.load(open(out + "/truth.json"))
            s = json.load(open(out + "/loop/loop_summary.json"))
            steps = [x["variable"] for x in s["steps"]]
            ratio = s["heldout_rms_N"] / noise
            if null:
                null_n += 1
                fa += bool(steps)
                ok = not steps
            else:
                eff_n += 1
                ok = bool(steps) and steps[0] in truth["aliases"] and ratio <= 2.0
                det += ok
            per.setdefault(e, [0, 0])
            per[e][0] += ok
            per[e][1] += 1
            print(f"{e:12s} noise {noise:2d} seed {seed}: {'ok' if ok else 'MISS/ALARM'} ratio {ratio:5.2f} steps {steps}",
                  flush=True)
for e, (a, b) in per.items():
    print(f"  {e:12s} {a}/{b}" + (" (null sets without a step)" if e == "none" else ""))
print(f"detected {det}/{eff_n}; null sets with a step {fa}/{null_n}")
