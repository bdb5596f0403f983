// The outcome of a solve in words, from the report of the program's JSON (the same words as the
// program's summary line: tools/fair-curves/kappa_command.cpp, optimal_command.cpp,
// cardinal_command.cpp). Returns {level: 'ok'|'warn'|'bad', text}.

function fmt(x, digits = 3) {
  if (typeof x !== 'number' || !isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e6 ? String(Number(x.toPrecision(digits))) : x.toExponential(digits - 1);
}

function pointList(points) {
  return (points.length === 1 ? ' point' : ' points') + points.map((p) => ' ' + p).join('');
}

function kappaWords(c) {
  const r = c.report || {};
  const head = `${c.pieces.length} pieces, ${c.closed ? 'closed' : 'open'}, weights ${c.weights}, ` +
    `${r.refinement_passes} passes and ${r.iterations} iterations, residual ${fmt(r.residuals ? r.residuals.max : NaN)}` +
    (r.warm_started ? ', warm' : '') + '; ';
  switch (r.status) {
    case 'interior':
      return { level: 'ok', text: head + 'interior: every point at a curvature maximum of its piece' };
    case 'on_joins':
      return { level: 'warn', text: head + 'on joins:' + pointList(r.points_on_joins || []) +
        ' on a join (t or lambda at 0 or 1), not at a curvature maximum; the rest interior' };
    default: {
      let why;
      if (r.reason === 'beyond_density_limit') {
        const d = r.points_beyond_density_limit || [];
        const shown = d.slice(0, 8);
        why = `no kappa-curve exists for this data: ${d.length} of ${c.points.length}` +
          (d.length === 1 ? ' points is' : ' points are') + ' beyond the density limit (kappa-curves need sparse points):' +
          pointList(shown) + (shown.length < d.length ? ' ...' : '') + '; csr and optimal are made for dense samples';
      } else if (r.reason === 'points_at_minima') {
        why = 'at a curvature minimum, not a maximum:' + pointList(r.points_at_minima || []);
      } else {
        why = `residual ${fmt(r.residuals ? r.residuals.max : NaN)} above the tolerance, worst` +
          (r.worst_points || []).map((p) => ` ${p.point} (${fmt(p.residual)})`).join('');
        if ((r.points_at_minima || []).length) why += '; at a curvature minimum, not a maximum:' + pointList(r.points_at_minima);
      }
      return { level: 'bad', text: head + 'unsolved (' + r.reason + '): ' + why };
    }
  }
}

function optimalWords(c) {
  const r = c.report || {};
  let text = `${c.closed ? 'closed' : 'open'}, ${c.points.length} points -> ${(c.polygon || []).length} vertices in ` +
    `${(r.levels || []).length} levels, ${r.iterations} iterations, energy ${fmt(r.energy, 6)}, spline fit within ` +
    `${fmt(c.fit_max_distance)}; ${r.status}`;
  let level = r.status === 'converged' ? 'ok' : 'bad';
  // The meanings of fair::Optimal_curve_status (include/fair/Optimal_curve_report.h).
  if (r.status === 'capped') text += ' (an iteration, level or vertex cap was hit first, or the solver failed)';
  if (r.status === 'diverging') text += ' (the curve runs away: no finite minimiser for these data and weights)';
  if (r.extent_ratio > 1.5 || r.self_intersections > r.input_self_intersections) {
    text += `; warning: the curve reaches ${fmt(r.extent_ratio)} times the extent of its points and has ` +
      `${r.self_intersections} self-intersection${r.self_intersections === 1 ? '' : 's'} (the input polygon ` +
      `${r.input_self_intersections}): not a fair curve for these data and weights`;
    level = 'bad';
  }
  return { level, text };
}

function cardinalWords(c) {
  const r = c.report || {};
  const why = r.status === 'optimal' ? 'optimal, eq. 18' : r.status === 'given_alpha' ? 'given'
    : 'eq. 18 has no positive optimum: Catmull-Rom';
  return { level: r.status === 'no_optimum' ? 'warn' : 'ok',
    text: `${c.points.length} points, ${c.closed ? 'closed' : 'open'}, ${c.pieces.length} cubic pieces, ${r.status}: ` +
      `alpha = ${fmt(r.alpha, 10)} (${why}), energy (eq. 10) ${fmt(r.energy, 6)}` };
}

function csrWords(c) {
  return { level: 'ok', text: `${c.points.length} samples, ${c.closed ? 'closed' : 'open'}, ${c.pieces.length} cubic pieces, ` +
    `knots ${c.knot_spacing}; approximates: max distance to the samples ${fmt(c.max_distance_to_samples)}` };
}

function splineWords(c) {
  return { level: 'ok', text: `${c.points.length} points, ${c.closed ? 'closed' : 'open'}, ${c.pieces.length} pieces` +
    (c.end ? `, end ${c.end}` : '') };
}

// The status line of a curve JSON of method `method`.
export function outcomeWords(method, curve) {
  let w;
  if (method === 'kappa') w = kappaWords(curve);
  else if (method === 'optimal') w = optimalWords(curve);
  else if (method === 'cardinal') w = cardinalWords(curve);
  else if (method === 'csr') w = csrWords(curve);
  else w = splineWords(curve);
  return { level: w.level, text: `${method}: ${w.text}` };
}

export { fmt };
