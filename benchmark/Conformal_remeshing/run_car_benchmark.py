#!/usr/bin/env python3
"""The car benchmark: the car-scale assembly (generate_car_model) remeshed end to end by
remesh_conformal in one process and by remesh_conformal_mpi on 2 and 3 ranks of this machine.

    python3 benchmark/Conformal_remeshing/run_car_benchmark.py [--scale full|small] [--ranks 1,2,3]
                                                               [--time-limit S] [OUT_DIR]

  --scale       full: at least 15M faces of parts at Table 1's sizes (the paper's car);
                small: at least 1.5M faces of parts at a tenth of those sizes [small]
  --ranks       the configurations: 1 is remesh_conformal itself, N > 1 remesh_conformal_mpi
                under mpirun -np N [1,2,3]
  --time-limit  seconds per run (the tools' --time-limit) [7200]
  OUT_DIR       where the model, outputs, reports and car.json go [out/car_benchmark_<scale>]

The target edge length is the one whose equilateral triangles cover the car's area with as many
vertices as the paper's output has in proportion (3,398k of 15,013k faces). Each run records the
wall seconds of the whole tool run (reading, remeshing, measuring, writing), the seconds of the
remeshing stages (from --report), the peak resident memory of the largest process (and of each
rank), the output's size and quality and the Hausdorff distances both ways. An MPI run's output is
compared byte for byte with the single process's. From the single process's per-job times
(--report's patch_job_seconds), the wall time on 4, 16 and 64 machines of this machine's cores is
projected by replaying the dispatcher (largest job first to the first free worker rank; rank 0
does the rest alone), without the network's time. Writes OUT_DIR/car.json and prints a table.
Exit code 0 when every run finished, 1 otherwise, 2 on a set-up error.
"""

import argparse
import heapq
import json
import math
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAPER_CAR_FACES, PAPER_CAR_OUTPUT_FACES = 15013000, 3398000


def run(command, **kwargs):
    print("+ " + " ".join(command), flush=True)
    return subprocess.run(command, **kwargs)


def build(build_dir):
    subprocess.run(["bash", os.path.join(ROOT, "scripts/install_dependencies.sh")], check=True)
    subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                    "-DCGAL_CONFORMAL_REMESHING_BUILD_EXAMPLES=ON"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", build_dir, "-j", str(os.cpu_count() or 2), "--target", "generate_car_model",
                    "remesh_conformal_tool", "remesh_conformal_mpi"], check=True)


def timed(command, log):
    """Runs `command` under GNU time: exit code, wall seconds, peak resident MB of the largest
    process it waited for (mpirun's ranks included)."""
    start = time.monotonic()
    with open(log, "w") as out:
        result = subprocess.run(["/usr/bin/time", "-f", "peak_kb %M"] + command, stdout=out, stderr=subprocess.STDOUT)
    seconds = time.monotonic() - start
    text = open(log).read()
    peaks = re.findall(r"peak_kb (\d+)", text)
    return result.returncode, seconds, (int(peaks[-1]) / 1024. if peaks else None), text


def replay(job_seconds, workers):
    """The meshing stage's wall time when `workers` ranks take the jobs largest first."""
    if workers < 1:
        return sum(job_seconds)
    free = [0.] * workers
    for s in sorted(job_seconds, reverse=True):
        heapq.heapreplace(free, free[0] + s)
    return max(free)


def main():
    parser = argparse.ArgumentParser(add_help=True, usage=__doc__.split("\n\n")[1].strip())
    parser.add_argument("--scale", choices=["full", "small"], default="small")
    parser.add_argument("--ranks", default="1,2,3")
    parser.add_argument("--time-limit", type=float, default=7200.)
    parser.add_argument("--no-fidelity", action="store_true",
                        help="the tools' --no-fidelity: no Hausdorff distances (they sample every face of both meshes)")
    parser.add_argument("out", nargs="?")
    args = parser.parse_args()
    ranks = [int(r) for r in args.ranks.split(",")]
    out = os.path.abspath(args.out or os.path.join(ROOT, "out", "car_benchmark_" + args.scale))
    os.makedirs(out, exist_ok=True)
    build_dir = os.environ.get("BUILD_DIR", os.path.join(ROOT, "build", "benchmark"))
    build(build_dir)
    bench = os.path.join(build_dir, "benchmark", "Conformal_remeshing")
    tools = os.path.join(build_dir, "examples", "Conformal_remeshing")

    faces, scale = (15000000, 1.) if args.scale == "full" else (1500000, 0.1)
    car = os.path.join(out, "car.off")
    generated = run([os.path.join(bench, "generate_car_model"), car, "--faces", str(faces), "--part-scale", str(scale),
                     "--parts", os.path.join(out, "parts.json")], capture_output=True, text=True, check=True).stdout
    summary = re.search(r"(\d+) parts, (\d+) vertices, (\d+) faces, area ([0-9.e+]+)", generated)
    parts, input_vertices, input_faces, area = int(summary[1]), int(summary[2]), int(summary[3]), float(summary[4])
    output_vertices = input_vertices * PAPER_CAR_OUTPUT_FACES / PAPER_CAR_FACES
    h = math.sqrt(2. * area / (math.sqrt(3.) * output_vertices))
    print(f"car: {parts} parts, {input_faces} faces; target edge length {h:.6g} for about {output_vertices:.0f} output vertices")

    records, single_output = [], None
    options = ["--target-edge-length", repr(h), "--quiet", "--time-limit", str(args.time_limit)]
    if args.no_fidelity:
        options.append("--no-fidelity")
    for n in ranks:
        name = "single" if n == 1 else f"mpi_{n}"
        output, report = os.path.join(out, name + ".off"), os.path.join(out, name + "_report.json")
        for f in (output, report):
            if os.path.exists(f):
                os.remove(f)
        if n == 1:
            command = [os.path.join(tools, "remesh_conformal"), car, output, "--report", report] + options
        else:
            command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(n),
                       os.path.join(tools, "remesh_conformal_mpi"), car, output, "--report", report] + options
        code, seconds, peak, text = timed(command, os.path.join(out, name + ".log"))
        record = {"configuration": name, "ranks": n, "input_faces": input_faces, "parts": parts,
                  "target_edge_length": h, "wall_seconds": seconds, "peak_mb": peak, "exit_code": code,
                  "status": "ok" if code == 0 and os.path.exists(report) else "failed"}
        per_rank = re.search(r"peak resident MB per rank: ([0-9., ]+)", text)
        if per_rank:
            record["peak_mb_per_rank"] = [float(x) for x in per_rank[1].split(",")]
        if record["status"] == "ok":
            r = json.load(open(report))
            q, f = r["output_quality"], r["fidelity"]
            if f is None:  # --no-fidelity
                f = {"relative_hausdorff_to_reference": None, "relative_hausdorff_from_reference": None,
                     "reference_diagonal": None, "self_intersects": r.get("output_self_intersects")}
            record.update({"output_faces": q["faces"], "output_vertices": q["vertices"],
                           "min_angle": q["minimum_angle"]["min"], "mean_skewness": q["equiangle_skewness"]["mean"],
                           "hausdorff_out_in": None if f["reference_diagonal"] is None
                           else f["relative_hausdorff_to_reference"] * f["reference_diagonal"],
                           "hausdorff_in_out": None if f["reference_diagonal"] is None
                           else f["relative_hausdorff_from_reference"] * f["reference_diagonal"],
                           "share_below_25_degrees": q["share_with_minimum_angle_below"]["25"],
                           "share_below_25_degrees_away_from_sharp_corners":
                           r["output_angles_at_sharp_input_corners"]["share_below_away_from_sharp_input_corners"],
                           "relative_hausdorff_out_in": f["relative_hausdorff_to_reference"],
                           "relative_hausdorff_in_out": f["relative_hausdorff_from_reference"],
                           "self_intersects": f["self_intersects"], "stage_seconds": r["seconds"],
                           # the tool's run until the output is remeshed: reading, checks, remeshing,
                           # without the fidelity measures (which sample every face) and the writing
                           "seconds_until_remeshed": r.get("seconds_until_remeshed"),
                           "peak_mb_until_remeshed": r.get("peak_resident_mb_until_remeshed"),
                           "component_batches": r["segmentation"].get("component_batches"),
                           "remesh_seconds": sum(r["seconds"][k] for k in ("segmentation", "flattening",
                                                                           "meshing_and_pull_back", "gluing"))})
            if n == 1:
                single_output = output
                jobs = r.get("patch_job_seconds", [])
                serial = record["remesh_seconds"] - r["seconds"]["meshing_and_pull_back"]
                cores = os.cpu_count() or 2
                record["projection"] = {
                    "patch_jobs": len(jobs), "rank_0_seconds": serial, "job_thread_seconds": sum(jobs),
                    "largest_job_seconds": max(jobs) if jobs else 0.,
                    "machines": {str(m): serial + replay(jobs, m * cores - 1) for m in (4, 16, 64)}}
            elif single_output:
                record["same_output_as_single"] = open(output, "rb").read() == open(single_output, "rb").read()
        else:
            record["error"] = text.strip().splitlines()[-3:] if text.strip() else []
        records.append(record)
        json.dump(records, open(os.path.join(out, "car.json"), "w"), indent=1)

    print("\n| configuration | ranks | wall s | remesh s | peak MB | output faces | min angle | mean skewness "
          "| Hausdorff out-in | in-out | same output |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in records:
        if r["status"] != "ok":
            print(f"| {r['configuration']} | {r['ranks']} | {r['wall_seconds']:.1f} | failed (exit {r['exit_code']}) |")
            continue
        print(f"| {r['configuration']} | {r['ranks']} | {r['wall_seconds']:.1f} | {r['remesh_seconds']:.1f} "
              f"| {r['peak_mb']:.0f} | {r['output_faces']} | {r['min_angle']:.2f} | {r['mean_skewness']:.3f} "
              f"| {r['hausdorff_out_in'] or float('nan'):.3g} | {r['hausdorff_in_out'] or float('nan'):.3g} "
              f"| {r.get('same_output_as_single', '')} |")
    for r in records:
        if "projection" in r:
            p = r["projection"]
            print(f"\nprojection ({p['patch_jobs']} patch jobs, {p['job_thread_seconds']:.1f} thread s, largest "
                  f"{p['largest_job_seconds']:.2f} s; rank 0 alone {p['rank_0_seconds']:.1f} s): "
                  + ", ".join(f"{m} machines {s:.1f} s" for m, s in p["machines"].items()))
    print(f"\nrecords: {os.path.join(out, 'car.json')}")
    return 0 if all(r["status"] == "ok" for r in records) else 1


if __name__ == "__main__":
    try:
        sys.exit(main())
    except subprocess.CalledProcessError as e:
        print(f"run_car_benchmark.py: {' '.join(e.cmd)} failed with exit code {e.returncode}", file=sys.stderr)
        sys.exit(2)
