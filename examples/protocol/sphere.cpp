// Nearest t > 0 on a sphere, in double; one answer line per case line.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
// The n numbers after "key": in a case line. strtod also reads nan and inf.
static void get(const std::string& s, const char* key, double* v, int n) {
  const char* c = s.c_str() + s.find(std::string("\"") + key + "\":") + std::strlen(key) + 3;
  for (char* end; n-- > 0; c = end) {
    while (*c && std::strchr("[, \"", *c)) c++;
    *v++ = std::strtod(c, &end);
  }
}
int main() {
  for (std::string line; std::getline(std::cin, line);) {
    double id, o[3], d[3], c[3], r;
    get(line, "id", &id, 1), get(line, "origin", o, 3), get(line, "dir", d, 3);
    get(line, "center", c, 3), get(line, "radius", &r, 1);
    double f[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
    double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], b = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
    double cc = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - r * r, disc = b * b - a * cc;
    double q = disc < 0 ? NAN : -(b + std::copysign(std::sqrt(disc), b)), r1 = q / a, r2 = cc / q;
    double t = r1 > 0 && !(r2 > 0 && r2 < r1) ? r1 : r2 > 0 ? r2 : NAN;  // NaN: no hit
    std::printf(std::isfinite(t) ? "{\"id\":%.0f,\"t\":%.17g}\n" : "{\"id\":%.0f,\"t\":null}\n", id, t);
    std::fflush(stdout);  // the gate waits for each answer
  }
}
