// three.js ray casts as a rayoracle gate kernel, speaking the stdio protocol
// (docs/protocol.md): one case line in on stdin, one answer line out.
//
//   node adapter.mjs sphere          Ray.intersectSphere(new Sphere(center, radius), target)
//   node adapter.mjs sphere-raw      the same, with the case's direction as given (use --unit-dirs)
//   node adapter.mjs plane           Ray.intersectPlane(plane, target)
//   node adapter.mjs plane-distance  Ray.distanceToPlane(plane)
//
// three.js computes in doubles (JavaScript numbers); the case's f32 values
// convert exactly. A three.js Ray wants a unit direction, so the ray is
// built as Raycaster builds it: new Ray(O, D.clone().normalize()), in
// double, and a distance s along that unit direction is the case's
// t = s / |D|. intersectSphere and intersectPlane return a point P (Ray.at)
// or null; s is then (P − O)·D̂, in double. The plane is
// Plane.setFromNormalAndCoplanarPoint(N.normalize(), point), since three.js
// asks for a unit normal too.
import { createInterface } from "node:readline";
import { Plane, Ray, Sphere, Vector3 } from "three";

const modes = ["sphere", "sphere-raw", "plane", "plane-distance"];
const mode = process.argv[2];
if (process.argv.length !== 3 || !modes.includes(mode)) {
  process.stderr.write(`usage: node adapter.mjs ${modes.join(" | ")}\n`);
  process.exit(2);
}

// Case numbers may be the strings "nan", "inf" and "-inf".
const num = (x) => (typeof x === "string" ? { nan: NaN, inf: Infinity, "-inf": -Infinity }[x] : x);
const vec = (v) => new Vector3(...v.map(num));
// JSON has no NaN or infinity (JSON.stringify writes null, "no hit"): send strings.
const json = (t) => (t === null || Number.isFinite(t) ? t : Number.isNaN(t) ? "nan" : t > 0 ? "inf" : "-inf");

createInterface({ input: process.stdin }).on("line", (line) => {
  const c = JSON.parse(line);
  const dir = vec(c.dir);
  const scale = mode === "sphere-raw" ? 1 : dir.length();
  const ray = new Ray(vec(c.origin), mode === "sphere-raw" ? dir : dir.clone().normalize());
  // The case's t of a distance s along ray.direction, or null for none.
  const t = (s) => (s === null ? null : s / scale);
  const at = (p) => t(p === null ? null : p.sub(ray.origin).dot(ray.direction) / ray.direction.lengthSq());
  let answer;
  if (mode === "sphere" || mode === "sphere-raw") {
    answer = at(ray.intersectSphere(new Sphere(vec(c.center), num(c.radius)), new Vector3()));
  } else {
    const plane = new Plane().setFromNormalAndCoplanarPoint(vec(c.normal).normalize(), vec(c.point));
    answer = mode === "plane" ? at(ray.intersectPlane(plane, new Vector3())) : t(ray.distanceToPlane(plane));
  }
  // On Linux, writes to a pipe are synchronous: each answer leaves at once.
  process.stdout.write(JSON.stringify({ id: c.id, t: json(answer) }) + "\n");
});
