import json, sys
from ref import run
from mpmath import mp
cases = {
 "hlw": dict(J=[2.0,1.0,2.0/3.0], m0=[__import__('math').cos(1.1),0.0,__import__('math').sin(1.1)], R0=[1,0,0,0], times=[20.0]),
 "sep_a": dict(J=[2.0,5.0,8.0], m0=[1.0,0.3,2.0], R0=[1,0,0,0], times=[20.0]),
 "sep_b": dict(J=[2.0,5.0,8.0], m0=[-1.0,-4.0,-2.0], R0=[1,0,0,0], times=[20.0]),
 "nearsep": dict(J=[2.0,5.0,8.0], m0=[1.0,0.3,2.0*(1.0+1e-12)], R0=[1,0,0,0], times=[20.0]),
 "sliver": dict(J=[1.0,1.000000001,2.0], m0=[0.6,-0.5,1e-9], R0=[1,0,0,0], times=[20.0]),
 "ns15": dict(J=[1.0,1.0+1e-15,2.0], m0=[0.6,-0.5,0.9], R0=[1,0,0,0], times=[20.0]),
 "ns15s": dict(J=[1.0,1.0+1e-15,2.0], m0=[0.6,-0.5,1e-9], R0=[1,0,0,0], times=[20.0]),
 "hvneg": dict(J=[0.6,0.8,1.0], m0=[-1.8,-0.4,0.9], R0=[0.5,0.5,-0.5,0.5], times=[7.3]),
 "dzh": dict(J=[3.0,5.0,9.0], m0=[0.0,2.0,0.01], R0=[1,0,0,0], times=[100.0]),
}
which = sys.argv[1:] or list(cases)
for name in which:
    c = cases[name]
    res = run(c["J"], c["m0"], c["R0"], c["times"])
    for t, Y in zip(c["times"], res):
        print(name, t, "M", [mp.nstr(v, 20) for v in Y[:9]], "m", [mp.nstr(v, 20) for v in Y[9:]], flush=True)
