// GLM's ray casts as a rayoracle gate kernel, speaking the stdio protocol
// (docs/protocol.md): one case line in on stdin, one answer line out.
//
//   adapter sphere-distance   glm::intersectRaySphere(orig, dir, center, r*r, distance)
//   adapter sphere-position   glm::intersectRaySphere(orig, dir, center, r, position, normal)
//   adapter plane             glm::intersectRayPlane(orig, dir, point, normalize(normal), distance)
//   adapter sphere-patched    the distance form with dSquared = |diff - t0*dir|^2 (see below)
//
// Every input is a float (glm::vec3): the case's numbers are f32 values, so
// the conversion is exact. The answer is the nearest t > 0 ({"t": x} or
// {"t": null}). GLM asks for a unit direction: run the gate with
// --unit-dirs. The plane normal is normalised here, in float, since
// intersectRayPlane asks for a unit normal too. The position form returns a
// point: its t is (position - orig)·dir / dir·dir, in double, so the answer
// carries the rounding of the float point GLM returns.
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtx/intersect.hpp>

#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

// The n numbers after "key": in a case line; strtod also reads the strings
// "nan", "inf" and "-inf" once their quotes are skipped.
static bool get(const std::string& s, const char* key, double* v, int n) {
  std::size_t at = s.find(std::string("\"") + key + "\":");
  if (at == std::string::npos) return false;
  const char* c = s.c_str() + at + std::strlen(key) + 3;
  for (char* end; n-- > 0; c = end) {
    while (*c != '\0' && std::strchr("[, \"", *c)) c++;
    *v++ = std::strtod(c, &end);
    if (end == c) return false;
  }
  return true;
}

static bool vec(const std::string& s, const char* key, glm::vec3& out) {
  double v[3];
  if (!get(s, key, v, 3)) return false;
  out = glm::vec3(float(v[0]), float(v[1]), float(v[2]));
  return true;
}

// glm::intersectRaySphere (distance form, GLM 0.9.9.8) with one change:
// the squared distance from the center to the ray is formed from the
// perpendicular vector, |diff - t0*dir|^2 (Ray Tracing Gems ch. 7, eq.
// 7.5), instead of dot(diff, diff) - t0*t0, which cancels. Everything else,
// the epsilons included, is GLM's.
static bool patched(glm::vec3 const& o, glm::vec3 const& dir, glm::vec3 const& center, float r2,
                    float& distance) {
  float const eps = std::numeric_limits<float>::epsilon();
  glm::vec3 const diff = center - o;
  float const t0 = glm::dot(diff, dir);
  glm::vec3 const perp = diff - t0 * dir;
  float const dSquared = glm::dot(perp, perp);
  if (dSquared > r2) return false;
  float const t1 = std::sqrt(r2 - dSquared);
  distance = t0 > t1 + eps ? t0 - t1 : t0 + t1;
  return distance > eps;
}

// A t as a JSON value: a number, or "nan", "inf", "-inf" (JSON has none).
static void answer(double id, bool hit, double t) {
  if (!hit) std::printf("{\"id\":%.0f,\"t\":null}\n", id);
  else if (std::isnan(t)) std::printf("{\"id\":%.0f,\"t\":\"nan\"}\n", id);
  else if (std::isinf(t)) std::printf("{\"id\":%.0f,\"t\":\"%s\"}\n", id, t > 0 ? "inf" : "-inf");
  else std::printf("{\"id\":%.0f,\"t\":%.17g}\n", id, t);
  std::fflush(stdout);  // the gate waits for each answer before the next case
}

int main(int argc, char** argv) {
  std::string mode = argc == 2 ? argv[1] : "";
  if (mode != "sphere-distance" && mode != "sphere-position" && mode != "plane" &&
      mode != "sphere-patched") {
    std::fprintf(stderr, "usage: %s sphere-distance | sphere-position | plane | sphere-patched\n",
                 argv[0]);
    return 2;
  }
  for (std::string line; std::getline(std::cin, line);) {
    double id = 0, r = 0;
    glm::vec3 o(0), d(0), c(0), n(0);
    bool ok = get(line, "id", &id, 1) && vec(line, "origin", o) && vec(line, "dir", d);
    bool sphere = mode != "plane";
    ok = ok && (sphere ? vec(line, "center", c) && get(line, "radius", &r, 1)
                       : vec(line, "point", c) && vec(line, "normal", n));
    if (!ok) {
      std::fprintf(stderr, "not a %s case line: %s\n", sphere ? "sphere" : "plane", line.c_str());
      return 1;
    }
    float rf = float(r), t = 0;
    if (mode == "sphere-distance") {
      bool hit = glm::intersectRaySphere(o, d, c, rf * rf, t);
      answer(id, hit, t);
    } else if (mode == "sphere-patched") {
      bool hit = patched(o, d, c, rf * rf, t);
      answer(id, hit, t);
    } else if (mode == "sphere-position") {
      glm::vec3 p(0), normal(0);
      bool hit = glm::intersectRaySphere(o, d, c, rf, p, normal);
      glm::dvec3 op = glm::dvec3(p) - glm::dvec3(o), dd = glm::dvec3(d);
      answer(id, hit, glm::dot(op, dd) / glm::dot(dd, dd));
    } else {
      bool hit = glm::intersectRayPlane(o, d, c, glm::normalize(n), t);
      answer(id, hit, t);
    }
  }
}
