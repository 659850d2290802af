#!/usr/bin/env python3
"""Regenerates the example projects in assets/ (one per InterIFS result plate + the Sierpinski
tetrahedron). The committed .gridifs files are the source of truth; this script records how they
were built. Run: scripts/make-examples.py"""
import json, math, os
ASSETS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets")
def fn(name, color, pal, translate=(0,0,0), rotate=(0,0,0), scale=(0.5,0.5,0.5), ops=(), res=(6,6,6), weight=1):
    return {"name":name,"resolution":list(res),"weight":weight,"color":list(color),"palette_index":pal,
            "muted":False,"placement":{"translate":list(translate),"rotate":list(rotate),"scale":list(scale)},"ops":list(ops)}
def project(fns, cam=None, samples=4000000):
    c={"yaw":30,"pitch":20,"distance":4.6,"target":[0,0,0],"fov":35,"ortho":False}
    if cam: c.update(cam)
    return {"format":"gridifs","version":1,"camera":c,
            "render":{"width":1024,"height":768,"samples":samples,"seed":1,"skip":20,"background":[0.02,0.02,0.03],"depth_cue":0.6},
            "functions":fns}
T=[(1,1,1),(1,-1,-1),(-1,1,-1),(-1,-1,1)]
COL=[(1,0.55,0.15),(0.2,0.65,1),(0.35,0.9,0.35),(0.95,0.3,0.5),(0.9,0.85,0.3)]
def tet(ops_for=lambda i: [], s=0.5, res=(6,6,6)):
    return [fn("f%d"%(i+1), COL[i], i/3, translate=tuple((1-s)*c for c in T[i]), scale=(s,s,s), ops=ops_for(i), res=res) for i in range(4)]
out={}
out["sierpinski_tetrahedron"]=project(tet(res=(2,2,2)))
# linear IFS: a 3D tree (trunk, crown continuation, three branches)
lin=[fn("trunk",(0.55,0.35,0.2),0.0,translate=(0,0,-0.7),scale=(0.06,0.06,0.3)),
     fn("crown",(0.3,0.8,0.3),0.3,translate=(0,0,0.25),rotate=(0,0,40),scale=(0.7,0.7,0.7)),
     fn("branch_a",(0.4,0.9,0.4),0.6,translate=(0.28,0,-0.15),rotate=(0,40,0),scale=(0.42,0.42,0.42)),
     fn("branch_b",(0.4,0.9,0.4),0.8,translate=(-0.14,0.24,-0.05),rotate=(-40,-20,120),scale=(0.42,0.42,0.42)),
     fn("branch_c",(0.4,0.9,0.4),1.0,translate=(-0.14,-0.24,0.05),rotate=(40,-20,240),scale=(0.42,0.42,0.42))]
out["linear_ifs"]=project(lin,{"pitch":10,"distance":2.6,"target":[0,0,0.05]})
out["twisted_functions"]=project(tet(lambda i: [{"type":"twist","axis":"z","profile":"linear","k":1.0 if i%2==0 else -1.0,"omega":1.0,"center":"grid","selection":[]}], s=0.45, res=(6,6,8)))
out["tapered_functions"]=project(tet(lambda i: [{"type":"taper","axis":["z","x","y","z"][i],"profile":["linear","sine","pingpong","sine"][i],"k":[0.5,0.3,0.35,-0.3][i],"omega":3.14159,"center":"grid","selection":[]}], s=0.45, res=(6,6,8)))
# Each grid is pulled toward a point off its own centre: the sub-tetrahedra bulge and pinch.
out["attracting_point"]=project(tet(lambda i: [{"type":"magnet","point":[0.6*T[(i+1)%4][0],0.6*T[(i+1)%4][1],0.6*T[(i+1)%4][2]],"dmax":1.6,"strength":0.55,"falloff":1.5}], s=0.52, res=(10,10,10)))
out["morphed_functions"]=project(tet(lambda i: [{"type":"morph","pairs":[[[0,0,0],[0.25*T[(i+1)%4][0],0.25*T[(i+1)%4][1],0.25*T[(i+1)%4][2]]],[[0.9,0.9,0.9],[0.9,0.9,0.9]],[[-0.9,-0.9,-0.9],[-0.9,-0.9,-0.9]]],"strength":1.0}], s=0.5, res=(8,8,8)))
calc={"type":"calculator","x":"x*cos(v1*sqrt(x^2+y^2)) - y*sin(v1*sqrt(x^2+y^2))","y":"x*sin(v1*sqrt(x^2+y^2)) + y*cos(v1*sqrt(x^2+y^2))","z":"z","vars":{"v1":{"value":0.2,"min":-1,"max":1},"v2":{"value":0,"min":-1,"max":1},"v3":{"value":0,"min":-1,"max":1}},"seed":7,"center":"grid","selection":[]}
def calcfor(i):
    c=dict(calc); 
    if i==0: c=json.loads(json.dumps(calc)); c["vars"]["v1"]["value"]=0.2
    else: c=json.loads(json.dumps(calc)); c["vars"]["v1"]["value"]=[0.2,0.8,-0.8,0.5][i]
    return [c]
# figure-14 expression (v1 = 0.2 on the first function as in the paper; stronger on the others so it shows)
out["universal_calculator"]=project(tet(calcfor, s=0.5, res=(8,8,8)))
out["bended_functions"]=project(tet(lambda i: [{"type":"bend","axis":"z","toward":["y","x","y","x"][i],"k":[0.9,0.9,-0.9,-0.9][i],"center":"grid","selection":[]}], s=0.48, res=(6,6,10)))
comb=lambda i: [
    {"type":"twist","axis":"z","profile":"sine","k":0.5,"omega":2.0,"center":"grid","selection":[]},
    {"type":"taper","axis":"z","profile":"linear","k":-0.25,"omega":1.0,"center":"grid","selection":[]},
    {"type":"bend","axis":"z","toward":"x","k":0.5 if i%2 else -0.5,"center":"grid","selection":[]},
    {"type":"magnet","point":[0,0,1.0],"dmax":1.0,"strength":0.25,"falloff":2.0},
    {"type":"scale","factors":[1,1,0.9],"center":"grid","selection":[{"i":[0,2],"j":[0,7],"k":[0,7],"op":"or"}]}]
out["combined_distortions"]=project(tet(comb, s=0.43, res=(8,8,8)))
for name,p in out.items():
    json.dump(p, open(os.path.join(ASSETS, "%s.gridifs"%name),"w"), indent=2)

json.dump(out["twisted_functions"], open(os.path.join(ASSETS, "default.gridifs"), "w"), indent=2)
