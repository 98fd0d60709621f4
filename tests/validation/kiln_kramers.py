#!/usr/bin/python3
"""Checks a `hikiln kiln` run with kramers.average_from set against Kramers-Croockewit.

    kiln_kramers.py RUN --max-deviation D --max-rise-deviation E [--steady S]

Fails unless, in RUN/summary.json: the solids mass balance closes to 1e-8 of the throughput;
the averaging window was steady (discharge over feed within S of 1, default 0.03); and the mean
bed depth of every compared cross-section is within D (relative) of the Kramers-Croockewit depth
computed with the repose angle measured in the same run, and the depth's rise from the start
section to the last compared one within E (relative) of the theory's rise.
"""
import argparse
import json
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run")
    parser.add_argument("--max-deviation", type=float, required=True)
    parser.add_argument("--max-rise-deviation", type=float, required=True)
    parser.add_argument("--steady", type=float, default=0.03)
    args = parser.parse_args()
    with open(os.path.join(args.run, "summary.json")) as f:
        summary = json.load(f)
    kc = summary.get("kramers_croockewit")
    failures = []
    if summary["balance_error_of_throughput"] > 1e-8:
        failures.append(f"mass balance {summary['balance_error_of_throughput']:.3g} of the "
                        "throughput > 1e-8")
    if kc is None or kc.get("max_rel_deviation") is None:
        failures.append(f"no Kramers-Croockewit comparison: {kc}")
    else:
        if abs(kc["outflow_over_feed"] - 1.0) > args.steady:
            failures.append(f"not steady: discharge / feed = {kc['outflow_over_feed']:.4f} over "
                            f"the window {kc['window_s']}")
        if kc["max_rel_deviation"] > args.max_deviation:
            failures.append(f"bed depth {100 * kc['max_rel_deviation']:.2f} % from "
                            f"Kramers-Croockewit > {100 * args.max_deviation:g} %")
        if abs(kc["rise_rel_deviation"]) > args.max_rise_deviation:
            failures.append(f"the depth rises {kc['rise_m']:.4f} m, Kramers-Croockewit "
                            f"{kc['rise_kramers_m']:.4f} m: {100 * kc['rise_rel_deviation']:.1f} "
                            f"% > {100 * args.max_rise_deviation:g} %")
        print(f"kiln_kramers: repose angle {kc['repose_angle_deg']:.2f} deg, start depth "
              f"{kc['start_depth_m']:.4f} m, discharge / feed {kc['outflow_over_feed']:.4f}, "
              f"largest deviation {100 * kc['max_rel_deviation']:.2f} %, rms "
              f"{100 * kc['rms_rel_deviation']:.2f} % over {kc['sections_compared']} sections, rise "
              f"{kc['rise_m']:.4f} m against {kc['rise_kramers_m']:.4f} m "
              f"({100 * kc['rise_rel_deviation']:+.1f} %)")
    for failure in failures:
        print("kiln_kramers: FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
