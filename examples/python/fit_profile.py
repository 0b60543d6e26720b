#!/usr/bin/python3
"""Fits the crank's profile of the paper's mechanism to a required motion with scipy.optimize.

The motion required of disk 4 (its angle link4.angle over the crank angle O_A.theta2 in [-50, 100] deg) is
taken from a design whose crank parabola has a = 0.55 and whose disk 4 pivots at x = 7.1 (JSON paths
links[1].contours[0].a and pairs[3].at[0].x). Starting from the example's a = 0.5, x = 7, least squares on the
angle differences (scipy.optimize.least_squares; every residual evaluation is one rollkin solve of a modified
scene) recovers the design.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/fit_profile.py [--target-a 0.55] [--target-x 7.1]

Prints the fitted parameters, their errors against the target design and the largest angle difference left;
exit status 1 when the fit misses the target by more than --tolerance (default 1e-6).
"""
import argparse
import pathlib
import sys

import numpy as np
import rollkin
from scipy.optimize import least_squares

SCENE = pathlib.Path(__file__).resolve().parent.parent / "paper_fourbar.json"
PATHS = ("links[1].contours[0].a", "pairs[3].at[0].x")
START, STOP, STEP = -50.0, 100.0, 2.0


def output_angle(base, params):
    """link4.angle over the sweep for the design `params` (a, pivot x); NaN where a pose is not solved."""
    table = base.modified(dict(zip(PATHS, map(float, params)))).solve(START, STOP, STEP)
    angle = table["link4.angle"].copy()
    angle[table["status"] != "ok"] = np.nan
    return angle


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--target-a", type=float, default=0.55)
    parser.add_argument("--target-x", type=float, default=7.1)
    parser.add_argument("--tolerance", type=float, default=1e-6, help="largest accepted parameter error")
    args = parser.parse_args()

    base = rollkin.load_scene(SCENE)
    target = output_angle(base, (args.target_a, args.target_x))
    if np.isnan(target).any():
        sys.exit("the target design does not move over the whole sweep; choose another")
    evaluations = [0]

    def residual(params):
        evaluations[0] += 1
        try:
            diff = output_angle(base, params) - target
        except rollkin.InputError:  # a trial design that is not a mechanism (e.g. a = 0)
            return np.full(target.shape, 1e3)
        return np.where(np.isnan(diff), 1e3, diff)  # unsolved poses: a large, finite penalty

    start = np.array([0.5, 7.0])
    fit = least_squares(residual, start, x_scale=np.array([0.1, 1.0]), diff_step=1e-7, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    error = fit.x - np.array([args.target_a, args.target_x])
    left = np.abs(residual(fit.x)).max()
    print("fitted a = %.12f, pivot x = %.12f (target %.12g, %.12g)" % (fit.x[0], fit.x[1], args.target_a, args.target_x))
    print("parameter errors %.2e, %.2e; largest angle difference left %.2e deg; %d solves (%s)"
          % (error[0], error[1], left, evaluations[0], fit.message))
    return 0 if np.abs(error).max() <= args.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
