#!/usr/bin/env python3
"""Work-precision comparison of rolling-disk against SciPy and another Rust engine, in one run.

The Rust side (`cargo bench --bench benches -- --scipy-reference`) prints, as JSON, the benchmark scene's
high-precision reference (with its validation) and the timings of the tool's own DOP853, of
two other Rust ODE crates on the same right-hand side (ode_solvers' DOP853, the tool's default
engine, and the DOP853 of `ivp`, a Rust port of solve_ivp) and of DOPRI5 over a tolerance
sweep. This script
then integrates the same equations of motion, eqs 23-25 of McDonald & McDonald (2001):

    (2k+1) w1' + a' W sin(a) = 0                                            (23)
    k W^2 sin(a) cos(a) + (2k+1) w1 W sin(a) - (k+1) a'' = (g/a) cos(a)     (24)
    W' sin(a) + 2 a' W cos(a) + 2 w1 a' = 0                                 (25)

with a plain-Python right-hand side (math module, a list returned: what a SciPy user writes),
through solve_ivp (DOP853 and RK45) and through scipy.integrate.ode('dop853') (Hairer's dop853;
since SciPy 1.15 a C translation of his Fortran), all with the tool's rule atol = 1e-2 rtol at
rtol 1e-6, 1e-9, 1e-12. Every error is measured the same way against the same reference (per
component, relative to the largest magnitude that component reaches on the reference, at the
final time). It prints the machine, the date, a work-precision table and the ratios at equal
error, and writes the table (JSON) and a figure (error against time and against evaluations).

Then the same with sampling on both sides, one row every millisecond, each side doing the same
work, two ways: the states alone at the rows (the tool's solver layer sampling on its dense
output, against solve_ivp DOP853 with `t_eval` on the same grid), and with the quantities the
tool's scene records (the scene run as `simulate` runs it, against `t_eval` followed by the
energy, its largest change and the normal force in numpy); each side's largest error in alpha
over the rows against the same reference, the ratio of times at equal alpha error.

Usage: compare.py [--quick] [--sampled-only] [--out DIR] [--repeats N] [--processes N]
"""

import argparse
import datetime
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time

import scipy
from scipy.integrate import ode, solve_ivp

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTOLS = [1e-6, 1e-9, 1e-12]


def machine():
    cpu = platform.processor() or "unknown cpu"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "cpu": cpu,
        "cores": os.cpu_count(),
        "system": f"{platform.system()} {platform.release()}",
        "python": platform.python_version(),
        "scipy": scipy.__version__,
    }


def rust_side(quick, processes):
    """The Rust side's JSON, run in `processes` separate processes (one with --quick): a
    process's own layout in memory moves its timings by up to a third from one process to the
    next, so each timed point's wall seconds are the median over the processes (each already
    the median of its runs); everything else is the first process's, the same in all."""
    cmd = ["cargo", "bench", "--quiet", "--bench", "benches", "--", "--scipy-reference"]
    if quick:
        cmd.append("--quick")
        processes = 1
    print("running:", " ".join(cmd), f"({processes} processes)", file=sys.stderr)
    runs = [json.loads(subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.PIPE,
                                      text=True).stdout) for _ in range(max(1, processes))]
    data = runs[0]
    for i, p in enumerate(data["rust"]):
        p["wall_seconds"] = statistics.median(r["rust"][i]["wall_seconds"] for r in runs)
    for i, p in enumerate(data["sampled"]["rust"]):
        for key in ("wall_seconds", "states_wall_seconds"):
            p[key] = statistics.median(r["sampled"]["rust"][i][key] for r in runs)
    data["processes"] = len(runs)
    return data


def plain_rhs(disk, counter):
    k, g_a = disk["k"], disk["g"] / disk["a"]

    def f(_t, y):
        counter[0] += 1
        alpha, alpha_dot, om, w = y
        s, c = math.sin(alpha), math.cos(alpha)
        return [
            alpha_dot,
            (k * om * om * s * c + (2.0 * k + 1.0) * w * om * s - g_a * c) / (k + 1.0),
            -(2.0 * alpha_dot * om * c + 2.0 * w * alpha_dot) / s,
            -alpha_dot * om * s / (2.0 * k + 1.0),
        ]

    return f


def error(y, ref, scale):
    return max(abs(a - b) / s for a, b, s in zip(y, ref, scale))


def timed(run, repeats, budget):
    walls, result = [], None
    start = time.perf_counter()
    for i in range(repeats):
        t = time.perf_counter()
        result = run()
        walls.append(time.perf_counter() - t)
        if i >= 1 and time.perf_counter() - start > budget:
            break
    return statistics.median(walls), len(walls), result


def python_runs(data, repeats, budget):
    s = data["start"]
    y0 = [s["alpha"], s["alpha_dot"], s["precession"], s["spin"]]
    t_end = data["t_end"]
    ref, scale = data["reference"]["y_final"], data["reference"]["scale"]
    rows = []
    for rtol in RTOLS:
        atol = data["atol_per_rtol"] * rtol
        for method in ["DOP853", "RK45"]:
            count = [0]
            f = plain_rhs(data["disk"], count)

            def ivp(f=f, method=method):
                return solve_ivp(f, (0.0, t_end), y0, method=method, rtol=rtol, atol=atol)

            wall, n, sol = timed(ivp, repeats, budget)
            rows.append({
                "solver": f"solve_ivp {method}", "rtol": rtol, "atol": atol,
                "evaluations": int(sol.nfev), "wall_seconds": wall, "runs": n,
                "final_error": error(sol.y[:, -1], ref, scale),
            })
        count = [0]
        f = plain_rhs(data["disk"], count)

        def fortran(f=f):
            r = ode(f).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
            r.set_initial_value(y0, 0.0)
            y = r.integrate(t_end)
            if not r.successful():
                raise RuntimeError(f"dop853 failed at rtol {rtol}")
            return y

        count[0] = 0
        fortran()
        evals = count[0]
        wall, n, y = timed(fortran, repeats, budget)
        rows.append({
            "solver": "ode dop853 (Hairer)", "rtol": rtol, "atol": atol,
            "evaluations": evals, "wall_seconds": wall, "runs": n,
            "final_error": error(y, ref, scale),
        })
    return rows


def recorded_quantities(sol, disk):
    """What the tool's sampled run records beside the states, in numpy over all rows at once:
    eq 26's energy E = m a^2 / 2 [(2k+1) w^2 + (k+1) alpha_dot^2 + k Omega^2 sin^2 alpha
    + 2 (g/a) sin alpha] at each row and its largest relative change from the start, and the
    normal force F_z (eqs 20, 23-25) at each row, whose first negative value is a loss of
    contact (the tool looks at its steps' ends and then at the rows of the steps next to a
    negative one; numpy has no steps to look at, so every row)."""
    import numpy as np

    k, a, m, g = disk["k"], disk["a"], disk["m"], disk["g"]
    alpha, alpha_dot, om, w = sol.y
    s, c = np.sin(alpha), np.cos(alpha)
    energy = 0.5 * m * a * a * ((2.0 * k + 1.0) * w * w + (k + 1.0) * alpha_dot * alpha_dot
                                + k * om * om * s * s + 2.0 * (g / a) * s)
    change = np.max(np.abs((energy - energy[0]) / energy[0]))
    alpha_ddot = (k * om * om * s * c + (2.0 * k + 1.0) * w * om * s - (g / a) * c) / (k + 1.0)
    acc1 = -a * alpha_ddot + a * w * om * s
    acc3 = a * alpha_dot * alpha_dot - a * w * om * c
    f1 = m * acc1 - m * g * c
    f3 = m * acc3 - m * g * s
    fz = -c * f1 - s * f3
    lost = np.flatnonzero(fz < 0.0)
    return energy, change, (lost[0] if lost.size else None)


def sampled_runs(data, repeats, budget):
    """solve_ivp DOP853 with t_eval on the Rust side's grid, timed with its sampling two ways
    (the states alone, as t_eval returns them; then with the quantities the tool's run records,
    in numpy), and its largest error in alpha over the rows against the Rust side's
    reference."""
    import numpy as np

    sampled = data["sampled"]
    grid = np.array(sampled["t"])
    alpha_ref = np.array(sampled["alpha"])
    s = data["start"]
    y0 = [s["alpha"], s["alpha_dot"], s["precession"], s["spin"]]
    rows = []
    for e in range(5, 14):
        rtol = 10.0 ** -e
        atol = data["atol_per_rtol"] * rtol
        f = plain_rhs(data["disk"], [0])

        def ivp(f=f, rtol=rtol, atol=atol):
            return solve_ivp(f, (0.0, data["t_end"]), y0, method="DOP853", rtol=rtol,
                             atol=atol, t_eval=grid)

        def ivp_recorded(ivp=ivp):
            sol = ivp()
            return sol, recorded_quantities(sol, data["disk"])

        wall, n, sol = timed(ivp, repeats, budget)
        if not sol.success or len(sol.t) != len(grid):
            continue
        wall_recorded, n_recorded, _ = timed(ivp_recorded, repeats, budget)
        rows.append({
            "solver": "solve_ivp DOP853 t_eval", "rtol": rtol, "atol": atol,
            "evaluations": int(sol.nfev), "wall_seconds": wall, "runs": n,
            "recorded_wall_seconds": wall_recorded, "recorded_runs": n_recorded,
            "alpha_error": float(np.max(np.abs(sol.y[0] - alpha_ref))),
        })
    return rows


def sampled_table(data, rows):
    """Two comparisons at equal error in alpha, each side doing the same work: the states
    alone at the rows (the tool's solver layer against t_eval), and the recorded quantities
    too (the tool's run as simulate runs it against t_eval and the same quantities in
    numpy)."""
    rust = [dict(p, final_error=p["alpha_error"]) for p in data["sampled"]["rust"]]
    print()
    print(f"sampled every {data['sampled']['sample']} s ({len(data['sampled']['t'])} rows), "
          f"error = largest |alpha - reference| over the rows")
    print(f"{'solver':<34}{'rtol':>7}{'states [s]':>12}{'recorded [s]':>14}{'alpha error':>13}")
    for p in rust:
        print(f"{'rolling-disk':<34}{p['rtol']:>7.0e}{p['states_wall_seconds']:>12.3e}"
              f"{p['wall_seconds']:>14.3e}{p['alpha_error']:>13.1e}")
    for r in rows:
        print(f"{r['solver']:<34}{r['rtol']:>7.0e}{r['wall_seconds']:>12.3e}"
              f"{r['recorded_wall_seconds']:>14.3e}{r['alpha_error']:>13.1e}")
    print(f"{'at equal alpha error':<34}{'rtol':>7}{'states':>12}{'recorded':>14}")
    for r in rows:
        states = at_error(rust, r["alpha_error"], "states_wall_seconds")
        recorded = at_error(rust, r["alpha_error"], "wall_seconds")
        r["tool_states_seconds_at_equal_error"] = states
        r["tool_seconds_at_equal_error"] = recorded
        r["states_time_ratio_at_equal_error"] = r["wall_seconds"] / states
        r["time_ratio_at_equal_error"] = r["recorded_wall_seconds"] / recorded
        print(f"{'solve_ivp / rolling-disk':<34}{r['rtol']:>7.0e}"
              f"{r['states_time_ratio_at_equal_error']:>11.1f}x"
              f"{r['time_ratio_at_equal_error']:>13.1f}x")
    sel = [r for r in rows if any(abs(r["rtol"] - x) < 1e-3 * x for x in RTOLS)]
    if sel:
        for key, what in [("states_time_ratio_at_equal_error", "the states alone"),
                          ("time_ratio_at_equal_error", "with the recorded quantities")]:
            ratios = ", ".join(f"{r[key]:.0f}x at rtol {r['rtol']:.0e}" for r in sel)
            print(f"solve_ivp DOP853 sampled, {what}, at equal alpha error: {ratios} the "
                  f"tool's time")


def at_error(points, err, key):
    """`key` (wall_seconds or evaluations) of a solver at final error `err`: log-log
    interpolation along its measured curve made monotone (the cheapest run reaching each
    error); the nearest end beyond the measured range."""
    pts = sorted((p["final_error"], p[key]) for p in points if p["final_error"] > 0)
    env = [(e, min(v for e2, v in pts if e2 <= e)) for e, _ in pts]
    for (e0, v0), (e1, v1) in zip(env, env[1:]):
        if e0 <= err <= e1 and e1 > e0:
            f = (math.log(err) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(v0) + f * (math.log(v1) - math.log(v0)))
    if not env:
        return float("nan")
    return env[0][1] if err < env[0][0] else env[-1][1]


def figure(rust, rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    series = {}
    for p in rust:
        series.setdefault(f"rolling-disk {p['method']}" if p["method"] not in OTHER_RUST
                          else f"{p['method']} (Rust)", []).append(p)
    for r in rows:
        series.setdefault(r["solver"], []).append(r)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for name, pts in sorted(series.items()):
        pts = sorted(pts, key=lambda p: p["rtol"])
        errs = [max(p["final_error"], 1e-17) for p in pts]
        axes[0].loglog([p["wall_seconds"] for p in pts], errs, "o-", label=name, ms=3)
        axes[1].loglog([p["evaluations"] for p in pts], errs, "o-", label=name, ms=3)
    axes[0].set_xlabel("wall time of one integration [s]")
    axes[1].set_xlabel("right-hand-side evaluations")
    for ax in axes:
        ax.set_ylabel("final error (relative to each component's range)")
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7)
    fig.suptitle("Benchmark scene, 10 s: work against precision")
    fig.tight_layout()
    fig.savefig(path)


# Rust crates timed by the Rust side besides the tool's own engine ("dop853"): ode_solvers (the
# tool's default engine) and ivp (a Rust port of solve_ivp), each on the tool's right-hand side.
OTHER_RUST = ("ode_solvers dop853", "ivp dop853")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="time each point once")
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "compare"))
    ap.add_argument("--repeats", type=int, default=15, help="most timed runs per Python point")
    ap.add_argument("--processes", type=int, default=5,
                    help="separate processes of the Rust side, whose timings' median is used")
    ap.add_argument("--sampled-only", action="store_true",
                    help="only the sampled comparison (no unsampled runs on the Python side)")
    args = ap.parse_args()
    repeats, budget = (1, 0.0) if args.quick else (args.repeats, 2.0)

    info = machine()
    data = rust_side(args.quick, args.processes)
    ref = data["reference"]
    print(f"{info['date']}; {info['cpu']} ({info['cores']} cores), {info['system']}; "
          f"Python {info['python']}, SciPy {info['scipy']}")
    print(f"scene {data['scene']}: {data['t_end']} s; reference {ref['settings']['method']} "
          f"rtol {ref['settings']['rtol']:.0e}, uncertainty {ref['uncertainty']:.1e}")
    rows = [] if args.sampled_only else python_runs(data, repeats, budget)
    rust = data["rust"]
    ours = [p for p in rust if p["method"] == "dop853"]

    print()
    print(f"{'solver':<24}{'rtol':>7}{'evals':>9}{'wall [s]':>11}{'error':>10}"
          f"{'tool evals@err':>16}{'tool time@err':>15}{'time ratio':>12}")
    for p in rust:
        if any(abs(p["rtol"] - r) < 1e-3 * r for r in RTOLS):
            name = p["method"] if p["method"] in OTHER_RUST else f"rolling-disk {p['method']}"
            print(f"{name:<24}{p['rtol']:>7.0e}{p['evaluations']:>9}{p['wall_seconds']:>11.3e}"
                  f"{p['final_error']:>10.1e}")
    others = rows + [dict(p, solver=p["method"]) for p in rust
                     if p["method"] in OTHER_RUST and "error" not in p
                     and any(abs(p["rtol"] - r) < 1e-3 * r for r in RTOLS)]
    for r in others:
        ev = at_error(ours, r["final_error"], "evaluations")
        wt = at_error(ours, r["final_error"], "wall_seconds")
        r["tool_evaluations_at_equal_error"] = ev
        r["tool_seconds_at_equal_error"] = wt
        r["time_ratio_at_equal_error"] = r["wall_seconds"] / wt
        print(f"{r['solver']:<24}{r['rtol']:>7.0e}{r['evaluations']:>9}{r['wall_seconds']:>11.3e}"
              f"{r['final_error']:>10.1e}{ev:>16.0f}{wt:>15.3e}{r['time_ratio_at_equal_error']:>11.1f}x")

    print()
    for name in ["solve_ivp DOP853", "solve_ivp RK45", "ode dop853 (Hairer)", *OTHER_RUST]:
        sel = [r for r in others if r["solver"] == name]
        if sel:
            ratios = [r["time_ratio_at_equal_error"] for r in sel]
            evr = [r["evaluations"] / r["tool_evaluations_at_equal_error"] for r in sel]
            fmt = (lambda x: f"{x:.0f}") if min(ratios) >= 10 else (lambda x: f"{x:.2f}")
            print(f"{name:<22} at equal error: {fmt(min(ratios))}x to {fmt(max(ratios))}x the tool's "
                  f"time, {min(evr):.2f}x to {max(evr):.2f}x its evaluations")
    ns = data["rhs_nanoseconds"]
    lat = data["rhs_latency_nanoseconds"]
    over = [p["wall_seconds"] / (p["evaluations"] * ns * 1e-9) - 1.0 for p in ours]
    over_lat = [(p["wall_seconds"] / p["evaluations"] * 1e9 - lat) / lat for p in ours]
    print(f"one right-hand side: {ns:.1f} ns alone (throughput), {lat:.1f} ns chained as a step's "
          f"stages are (latency)")
    print(f"tool's DOP853 overhead per evaluation: {min(over_lat):.2f} to {max(over_lat):.2f} times "
          f"the chained right-hand side, {min(over):.2f} to {max(over):.2f} times the throughput "
          f"figure (target <= 0.5)")

    sampled_rows = sampled_runs(data, repeats, budget)
    sampled_table(data, sampled_rows)

    os.makedirs(args.out, exist_ok=True)
    sampled = {k: v for k, v in data["sampled"].items() if k not in ("t", "alpha")}
    with open(os.path.join(args.out, "compare.json"), "w") as f:
        json.dump({"machine": info, "reference": ref, "rust": rust, "python": rows,
                   "sampled": dict(sampled, python=sampled_rows),
                   "rhs_nanoseconds": ns, "rhs_latency_nanoseconds": lat}, f, indent=1)
    fig_path = os.path.join(args.out, "work_precision.svg")
    figure(rust, rows, fig_path)
    print(f"wrote {os.path.join(args.out, 'compare.json')} and {fig_path}")


if __name__ == "__main__":
    main()
