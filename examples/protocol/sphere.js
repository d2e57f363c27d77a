// Nearest t > 0 on a sphere, in double; one answer line per case line.
const readline = require("node:readline");
// Case numbers may be the strings "nan", "inf" and "-inf".
const num = (x) => (typeof x === "string" ? { nan: NaN, inf: Infinity, "-inf": -Infinity }[x] : x);
const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
readline.createInterface({ input: process.stdin }).on("line", (line) => {
  const c = JSON.parse(line);
  const [o, d, ce] = [c.origin, c.dir, c.center].map((v) => v.map(num));
  const r = num(c.radius);
  const f = [0, 1, 2].map((i) => o[i] - ce[i]);
  const a = dot(d, d), b = dot(f, d), cc = dot(f, f) - r * r, disc = b * b - a * cc;
  let t = null;
  if (disc >= 0 && b * b + disc > 0) {
    const q = -(b + Math.sign(b || 1) * Math.sqrt(disc));
    const [lo, hi] = [q / a, cc / q].sort((x, y) => x - y);
    t = lo > 0 ? lo : hi > 0 ? hi : null;
  }
  // JSON.stringify writes NaN and Infinity as null ("no hit"): send strings.
  if (t !== null && !Number.isFinite(t)) t = Number.isNaN(t) ? "nan" : t > 0 ? "inf" : "-inf";
  // On Linux, writes to a pipe are synchronous, so each line leaves at once.
  process.stdout.write(JSON.stringify({ id: c.id, t }) + "\n");
});
