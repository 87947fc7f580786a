import sys, time
from mpmath import mp, mpf, odefun, cos, sin, matrix
mp.dps = 32
def run(J, m0, R0, times):
    # R0 as rotor [s,e12,e13,e23] -> quaternion (s,-e23,e13,-e12) -> matrix
    s, b12, b13, b23 = [mpf(x) for x in R0]
    w, x, y, z = s, -b23, b13, -b12
    n = (w*w+x*x+y*y+z*z)**0.5; w,x,y,z = w/n,x/n,y/n,z/n
    M = [[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
         [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
         [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]]
    J = [mpf(v) for v in J]
    y0 = [M[i][k] for i in range(3) for k in range(3)] + [mpf(v) for v in m0]
    def f(t, Y):
        m = Y[9:]
        wv = [m[0]/J[0], m[1]/J[1], m[2]/J[2]]
        wx = [[0, -wv[2], wv[1]], [wv[2], 0, -wv[0]], [-wv[1], wv[0], 0]]
        out = []
        for i in range(3):
            for k in range(3):
                out.append(sum(Y[3*i+l]*wx[l][k] for l in range(3)))
        out += [m[1]*wv[2]-m[2]*wv[1], m[2]*wv[0]-m[0]*wv[2], m[0]*wv[1]-m[1]*wv[0]]
        return out
    sol = odefun(f, 0, y0)
    res = []
    for t in times:
        Y = sol(mpf(t))
        res.append(Y)
    return res
if __name__ == "__main__":
    import json
    spec = json.loads(sys.argv[1])
    t0=time.time()
    res = run(spec["J"], spec["m0"], spec["R0"], spec["times"])
    for t, Y in zip(spec["times"], res):
        print(t, "M", [mp.nstr(v, 20) for v in Y[:9]], "m", [mp.nstr(v, 20) for v in Y[9:]])
    print("elapsed", time.time()-t0, file=sys.stderr)
