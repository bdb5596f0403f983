// The options panel's controls (doc/editor.md): one control per option of GET /api/methods, with
// widgets for the options that have named values (kappa weights 1 / auto / a value, Cardinal alpha
// optimal / a value, optimal lambda as a slider with its per-segment switch, end conditions, knot
// spacing, solver); file options as rows of numbers, list options as words, the rest as text.

// A control for the option `opt` ({name, type, help, default}) showing `value`; `set(v)` stores a
// new value ('' or false: omitted from the request) and re-solves; `perSegment` {get, set} is the
// per-segment lambda switch.
export function optionControl(opt, value, set, perSegment) {
  const row = document.createElement('div');
  row.className = 'row';
  const number = (v, attrs = {}) => {
    const i = document.createElement('input');
    i.type = 'number';
    Object.assign(i, attrs);
    i.value = v;
    return i;
  };
  const choice = (items, current) => {
    const s = document.createElement('select');
    for (const it of items) { const o = document.createElement('option'); o.value = it; o.textContent = it; s.appendChild(o); }
    s.value = current;
    return s;
  };
  if (opt.type === 'flag') {
    const i = document.createElement('input');
    i.type = 'checkbox'; i.checked = !!value;
    i.addEventListener('change', () => set(i.checked));
    row.appendChild(i);
  } else if (opt.name === 'weights' || opt.name === 'alpha') {
    // 1 / auto / a value (kappa); optimal / a value (cardinal).
    const named = opt.name === 'weights' ? ['1', 'auto'] : ['optimal'];
    const isValue = value !== undefined && value !== '' && !named.includes(String(value));
    const s = choice([...named, 'value'], isValue ? 'value' : String(value || named[0]));
    const n = number(isValue ? value : (opt.name === 'weights' ? 0.8 : 0.5), { step: 0.05, min: 0 });
    n.hidden = !isValue;
    const apply = () => { n.hidden = s.value !== 'value'; set(s.value === 'value' ? n.value : (s.value === named[0] ? '' : s.value)); };
    s.addEventListener('change', apply);
    n.addEventListener('input', apply);
    row.append(s, n);
  } else if (opt.name === 'lambda') {
    const r = document.createElement('input');
    r.type = 'range'; r.min = 0; r.max = 1; r.step = 0.01; r.value = value === undefined || value === '' ? 0.7 : value;
    const out = document.createElement('span');
    out.textContent = Number(r.value).toFixed(2);
    r.addEventListener('input', () => { out.textContent = Number(r.value).toFixed(2); set(r.value); });
    const per = document.createElement('label');
    per.innerHTML = '<input type="checkbox"> per segment';
    const pc = per.querySelector('input');
    pc.checked = perSegment.get();
    pc.addEventListener('change', () => perSegment.set(pc.checked));
    row.append(r, out, per);
  } else if (['end', 'knots', 'solver'].includes(opt.name)) {
    const items = { end: ['natural', 'not-a-knot', 'clamped'], knots: ['chordal', 'uniform', 'centripetal'], solver: ['newton', 'cg'] }[opt.name];
    const s = choice(items, value || items[0]);
    s.addEventListener('change', () => set(s.value === items[0] ? '' : s.value));
    row.appendChild(s);
  } else if (opt.name === 'corners') {
    row.innerHTML = '<span class="muted">select a point, then “corner” below or the C key</span>';
  } else if (opt.name === 'tangents') {
    // Typed rows "i tx ty", and the per-point toggle (T) added to them.
    const t = document.createElement('textarea');
    t.placeholder = 'rows "i tx ty"; or select a point and press T';
    t.value = Array.isArray(value) ? value.map((r) => (Array.isArray(r) ? r.join(' ') : r)).join('\n') : '';
    t.addEventListener('change', () => {
      const rows = t.value.split('\n').map((l) => l.trim()).filter((l) => l && !l.startsWith('#')).map((l) => l.split(/[\s,]+/).map(Number));
      set(rows.length ? rows : '');
    });
    row.appendChild(t);
  } else if (opt.name === 'lambda-file') {
    row.innerHTML = '<span class="muted">per segment λ: tick “per segment”, select a point: its λ is the segment after it</span>';
  } else if (opt.type === 'file') {
    // Rows of numbers, one per line (tangents "i tx ty", normals, tension ...).
    const t = document.createElement('textarea');
    t.placeholder = 'one row per line, numbers separated by spaces';
    t.value = Array.isArray(value) ? value.map((r) => (Array.isArray(r) ? r.join(' ') : r)).join('\n') : '';
    t.addEventListener('change', () => {
      const rows = t.value.split('\n').map((l) => l.trim()).filter((l) => l && !l.startsWith('#'))
        .map((l) => { const v = l.split(/[\s,]+/).map(Number); return v.length === 1 ? v[0] : v; });
      set(rows.length ? rows : '');
    });
    row.appendChild(t);
  } else if (opt.type === 'list') {
    const i = document.createElement('input');
    i.type = 'text'; i.placeholder = 'values separated by spaces';
    i.value = Array.isArray(value) ? value.join(' ') : '';
    i.addEventListener('change', () => { const v = i.value.trim().split(/\s+/).filter(Boolean); set(v.length ? v : ''); });
    row.appendChild(i);
  } else {
    const i = document.createElement('input');
    i.type = 'text'; i.placeholder = opt.default || '';
    i.value = value === undefined ? '' : value;
    i.addEventListener('change', () => set(i.value.trim()));
    row.appendChild(i);
  }
  return row;
}
