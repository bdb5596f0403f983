// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// The double-precision solver behind fair::Kappa_curve_2: rational kappa-curves of
// Yan, Schiller, Schaefer, "Circle reproduction with interpolatory curves at local maximal
// curvature points" (equation numbers refer to that paper; weights w = 1 give the polynomial
// kappa-curves of Yan et al. 2017). This file is the map; each concept has its own file.
//
// The system (unknowns P_i, lambda_i, t_i per block; residuals of eqs. 7, 10, 18: a square
// 4n x 4n system) is in system.h, its Jacobian in jacobian.h, the initial guess and alternating
// passes of Section 5.1 in refinement.h. The paper's energy (eq. 17/19) is a sum of squares of
// the same conditions (differently normalised); its minimum value zero is reached exactly at a
// root of the system, so the solver looks for a root and stops when max |r| <= tolerance.
//
//  - solve_settings.h: the tolerance and iteration caps (Solve_settings, from
//    Kappa_curve_options), the projection margin of the bounds 0 < lambda_i, t_i < 1.
//  - block_range.h: the blocks a solve works on (all, or a range for the local warm start).
//  - active_set.h: the t_i bounds as box constraints of an active-set method (a t_i on its face
//    is fixed with its eq. 7 dropped, released by the sign of its multiplier; doc/kappa_curves.md,
//    "Points on joins"), so that a root on joins (ON_JOINS) is solved to the tolerance like an
//    interior one.
//  - newton.h: Newton's method, J delta = -r solved directly by the O(n) block LU of
//    linear_algebra/block_band_lu.h (Woodbury correction for the wrap-around of closed curves),
//    an Armijo line search and chord steps; converges in 2-4 Jacobians from two refinement
//    passes on typical data.
//  - pivoted_fallback.h: a pivoted band LU of the same Jacobian when the block LU meets a
//    singular pivot block.
//  - levenberg_marquardt.h: the robust fallback far from a root (J^T J banded, Cholesky).
//  - fallback.h: Levenberg-Marquardt, then a Newton polish, with one restart.
//  - steering.h: Sec. 3.2, moving points off curvature minima of their pieces.
//  - weight_continuation.h: automatic weights without a kappa-curve, continued from the w = 1
//    kappa-curve along w(s) = 1 + s (w~ - 1) (issue 24; start_strategy.h, cold_solve).
//  - outcome.h: Kappa_curve_status and the report of a finished solve.
//  - start_strategy.h: cold and warm starts, and the warm/cold policy of Kappa_curve_2
//    (solve_with_warm_start). Non-convergence within the iteration caps is reported
//    (Kappa_curve_report::status UNSOLVED); the caller decides whether to throw.
// Every method is O(n) per iteration because every residual depends on the unknowns of blocks
// i-2..i+1 only.

#ifndef FAIR_INTERNAL_KAPPA_SOLVER_H
#define FAIR_INTERNAL_KAPPA_SOLVER_H

#include <fair/internal/kappa/start_strategy.h>

#endif // FAIR_INTERNAL_KAPPA_SOLVER_H
