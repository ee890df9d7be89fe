import sys
def read(path):
    out={}; cur=None
    for line in open(path):
        t=line.split()
        if len(t)==2 and t[0]=="NOEUD": cur=t[1]; out[cur]=[]; continue
        if cur and len(t)==2 and t[0].startswith("N"):
            try: out[cur].append(float(t[1]))
            except ValueError: pass
    return out
print("| mesh (LOW / UP, cells along the interface) | formulation | SIYY min | SIYY max | LAGS_C min | LAGS_C max | max error |")
print("|---|---|---|---|---|---|---|")
names={"q4_q4":"QUAD4 (4) / QUAD4 (3)","t6_t6":"TRIA6 (4) / TRIA6 (3)","t3_q4":"TRIA3 (4) / QUAD4 (3)"}
for v in ["q4_q4","t3_q4","t6_t6"]:
    for f in ["DISCRETE","CONTINUE","LAC"]:
        d=read(f"cmp_{v}_{f}.resu")
        s=d.get("SIYY",[]); l=d.get("LAGS_C",[])
        vals=s+l
        err=max(abs(x+25)/25 for x in vals)
        lc=f"{min(l):.4f} | {max(l):.4f}" if l else "- | -"
        print(f"| {names[v]} | {f} | {min(s):.4f} | {max(s):.4f} | {lc} | {100*err:.2f} % |")
