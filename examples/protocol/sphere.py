# Nearest t > 0 on a sphere, in double; one answer line per case line.
import json
import math
import sys

for line in sys.stdin:
    case = json.loads(line)
    # float() also reads the strings "nan", "inf" and "-inf".
    o, d, c = ([float(x) for x in case[k]] for k in ("origin", "dir", "center"))
    r = float(case["radius"])
    f = [o[i] - c[i] for i in range(3)]
    a = sum(x * x for x in d)
    b = sum(f[i] * d[i] for i in range(3))
    cc = sum(x * x for x in f) - r * r
    disc = b * b - a * cc
    t = None
    if disc >= 0 and b * b + disc > 0:
        q = -(b + math.copysign(math.sqrt(disc), b))
        lo, hi = sorted((q / a, cc / q))
        t = lo if lo > 0 else hi if hi > 0 else None
    # JSON has no NaN or infinity: send those as the strings "nan", "inf".
    if t is not None and not math.isfinite(t):
        t = str(t)
    print(json.dumps({"id": case["id"], "t": t}), flush=True)
