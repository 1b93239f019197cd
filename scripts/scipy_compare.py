#!/usr/bin/env python3
"""The benchmark scene in SciPy against rolling-disk, timed in the same run.

Runs the Rust side (`cargo bench --bench scipy_reference`, which prints the reference final
state, its validation and the Rust timings as JSON), then integrates the same equations of
motion, eqs 23-25 of McDonald & McDonald (2001), with the same constants and start:

    (2k+1) w1' + a' W sin(a) = 0                                            (23)
    k W^2 sin(a) cos(a) + (2k+1) w1 W sin(a) - (k+1) a'' = (g/a) cos(a)     (24)
    W' sin(a) + 2 a' W cos(a) + 2 w1 a' = 0                                 (25)

with SciPy's solve_ivp(method='DOP853') and with the Fortran dop853 behind
scipy.integrate.ode('dop853'), at rtol 1e-6, 1e-9, 1e-12 (atol = 1e-2 rtol, the Rust rule),
measures their errors against the same reference with the same measure (per component,
relative to the largest magnitude that component reaches on the reference), and prints the
ratio of wall times at equal error.

It installs nothing: scripts/scipy_compare.sh provides numpy and scipy.

Usage: scipy_compare.py [--no-drift] [--json FILE] [--repeats N]
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import ode, solve_ivp

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTOLS = [1e-6, 1e-9, 1e-12]


def rust_side(drift):
    cmd = ["cargo", "bench", "--quiet", "--bench", "scipy_reference", "--"]
    if drift:
        cmd.append("--drift")
    print("running:", " ".join(cmd), file=sys.stderr)
    out = subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.PIPE, text=True)
    return json.loads(out.stdout)


def make_rhs(disk):
    k, a, g = disk["k"], disk["a"], disk["g"]
    g_a = g / a

    def rates(alpha, alpha_dot, om, w):
        s, c = math.sin(alpha), math.cos(alpha)
        spin_dot = -alpha_dot * om * s / (2.0 * k + 1.0)
        alpha_ddot = (k * om * om * s * c + (2.0 * k + 1.0) * w * om * s - g_a * c) / (k + 1.0)
        om_dot = -(2.0 * alpha_dot * om * c + 2.0 * w * alpha_dot) / s
        return [alpha_dot, alpha_ddot, om_dot, spin_dot]

    def rhs_ivp(_t, y):
        return np.array(rates(y[0], y[1], y[2], y[3]))

    def rhs_ode(_t, y):
        return rates(y[0], y[1], y[2], y[3])

    return rhs_ivp, rhs_ode


def error(y, ref, scale):
    return max(abs(a - b) / s for a, b, s in zip(y, ref, scale))


def timed(run, repeats, budget=2.0):
    walls, result = [], None
    start = time.perf_counter()
    for i in range(repeats):
        t = time.perf_counter()
        result = run()
        walls.append(time.perf_counter() - t)
        if i >= 2 and time.perf_counter() - start > budget:
            break
    return statistics.median(walls), len(walls), result


def scipy_runs(data, repeats):
    rhs_ivp, rhs_ode = make_rhs(data["disk"])
    s = data["start"]
    y0 = [s["alpha"], s["alpha_dot"], s["precession"], s["spin"]]
    t_end = data["t_end"]
    ref = data["reference"]["y_final"]
    scale = data["reference"]["scale"]
    rows = []
    for rtol in RTOLS:
        atol = data["atol_per_rtol"] * rtol

        def ivp():
            return solve_ivp(rhs_ivp, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol)

        wall, n, sol = timed(ivp, repeats)
        rows.append({
            "solver": "solve_ivp DOP853", "rtol": rtol, "atol": atol,
            "evaluations": int(sol.nfev), "wall_seconds": wall, "runs": n,
            "final_error": error(sol.y[:, -1], ref, scale),
        })

        count = [0]

        def counting(t, y):
            count[0] += 1
            return rhs_ode(t, y)

        def fortran(f=rhs_ode):
            r = ode(f).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
            r.set_initial_value(y0, 0.0)
            y = r.integrate(t_end)
            assert r.successful()
            return y

        wall, n, y = timed(fortran, repeats)
        fortran(counting)
        rows.append({
            "solver": "ode dop853 (Fortran)", "rtol": rtol, "atol": atol,
            "evaluations": count[0], "wall_seconds": wall, "runs": n,
            "final_error": error(y, ref, scale),
        })
    return rows


def rust_time_at(rust, err):
    """Wall time of Rust DOP853 at error `err`: (log-log interpolation along the measured
    curve, the cheapest measured run at least as accurate)."""
    pts = sorted((p["final_error"], p["wall_seconds"]) for p in rust
                 if p["method"] == "dop853" and p["final_error"] > 0)
    at_least = min((w for e, w in pts if e <= err), default=float("nan"))
    # Monotone envelope, from the most accurate: the cheapest time reaching each error level.
    env, best = [], float("inf")
    for e, w in pts:
        best = min(best, w)
        env.append((e, min(w for e2, w2 in pts if e2 <= e)))
    interp = float("nan")
    for (e0, w0), (e1, w1) in zip(env, env[1:]):
        if e0 <= err <= e1 and e1 > e0:
            f = (math.log(err) - math.log(e0)) / (math.log(e1) - math.log(e0))
            interp = math.exp(math.log(w0) + f * (math.log(w1) - math.log(w0)))
            break
    if math.isnan(interp) and env:
        interp = env[0][1] if err < env[0][0] else env[-1][1]
    return interp, at_least


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--no-drift", action="store_true", help="skip the long energy-drift runs")
    ap.add_argument("--json", help="also write everything as JSON to this file")
    ap.add_argument("--repeats", type=int, default=15, help="most timed runs per SciPy point")
    args = ap.parse_args()

    data = rust_side(not args.no_drift)
    ref = data["reference"]
    print(f"scene {data['scene']}: {data['t_end']} s, reference {ref['settings']['method']} "
          f"rtol {ref['settings']['rtol']:.0e} ({ref['evaluations']} evaluations, "
          f"uncertainty {ref['uncertainty']:.1e})")
    for a in ref["agreements"]:
        print(f"  agrees with {a['label']:<18} to {max(a['final_error'], a['trajectory_error']):.1e}")

    rows = scipy_runs(data, args.repeats)
    rust = data["rust"]
    by_rtol = {p["rtol"]: p for p in rust if p["method"] == "dop853"}
    print()
    print(f"{'solver':<22}{'rtol':>7}{'evals':>8}{'wall [s]':>11}{'error':>10}"
          f"{'rust@err [s]':>14}{'ratio':>9}{'ratio same rtol':>17}")
    for p in rust:
        if p["method"] == "dop853" and any(abs(p["rtol"] - r) < 1e-3 * r for r in RTOLS):
            print(f"{'rolling-disk dop853':<22}{p['rtol']:>7.0e}{p['evaluations']:>8}"
                  f"{p['wall_seconds']:>11.3e}{p['final_error']:>10.1e}")
    for r in rows:
        interp, at_least = rust_time_at(rust, r["final_error"])
        r["rust_seconds_at_equal_error"] = interp
        r["rust_seconds_at_least_as_accurate"] = at_least
        r["speedup_at_equal_error"] = r["wall_seconds"] / interp
        same = min(by_rtol.items(), key=lambda kv: abs(math.log(kv[0] / r["rtol"])))[1]
        r["speedup_at_same_rtol"] = r["wall_seconds"] / same["wall_seconds"]
        print(f"{r['solver']:<22}{r['rtol']:>7.0e}{r['evaluations']:>8}{r['wall_seconds']:>11.3e}"
              f"{r['final_error']:>10.1e}{interp:>14.3e}{r['speedup_at_equal_error']:>9.0f}"
              f"{r['speedup_at_same_rtol']:>17.0f}")

    print()
    ns = data["rhs_nanoseconds"]
    over = [p["overhead"] for p in rust if p["method"] == "dop853"]
    print(f"one right-hand side: {ns:.1f} ns; wall / (evaluations x that), dop853: "
          f"{min(over):.2f} to {max(over):.2f} (target <= 2)")
    ivp = [r for r in rows if r["solver"].startswith("solve_ivp")]
    fort = [r for r in rows if r["solver"].startswith("ode")]
    print(f"speed-up at equal error: solve_ivp {min(r['speedup_at_equal_error'] for r in ivp):.0f}x"
          f" to {max(r['speedup_at_equal_error'] for r in ivp):.0f}x (target >= 50x); "
          f"Fortran dop853 {min(r['speedup_at_equal_error'] for r in fort):.0f}x"
          f" to {max(r['speedup_at_equal_error'] for r in fort):.0f}x (target >= 10x)")
    for d in data.get("drift", []):
        if "drift" in d:
            x = d["drift"]
            print(f"energy drift over {d['periods']:.0e} precession periods, dop853 rtol 1e-13: "
                  f"max {x['max_abs_drift']:.1e} (target < 1e-12 over 1e4), growth t^"
                  f"{x['growth_exponent']:.2f}; sqrt(n) eps = {x['random_walk_bound']:.1e}, "
                  f"n eps = {x['linear_bound']:.1e} ({x['wall_seconds']:.1f} s)")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"rust": data, "scipy": rows}, f, indent=2)


if __name__ == "__main__":
    main()
