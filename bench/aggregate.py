#!/usr/bin/env python3
"""Pools the samples of a bench/run.sh log folder (hikari.jsonl, embree.log, pov_*.log, cycles.log, osmesa.log)
and prints markdown tables: medians (and min-max) for hikari and the peer, and hikari / peer ratios
(throughput: higher is better for hikari; times: peer / hikari, so > 1 means hikari is faster).
B4 (rasterization beside llvmpipe) has a table of its own, with both of llvmpipe's malloc settings."""
import json, os, re, statistics, sys

log = sys.argv[1]
hik, emb, pov = [], [], {}
p = os.path.join(log, "hikari.jsonl")
if os.path.exists(p):
    hik = [json.loads(l) for l in open(p) if l.strip()]
p = os.path.join(log, "embree.log")
if os.path.exists(p):
    emb = [dict(re.findall(r"(\w+)=(\S+)", l)) for l in open(p) if l.startswith("RESULT")]
for f in sorted(os.listdir(log)):
    m = re.match(r"pov_t(\d)_r\d+\.log", f)
    if m:
        s = open(os.path.join(log, f)).read()
        t = re.search(r"Trace Time:.*?\(([\d.]+) seconds\)", s)
        w = re.search(r"WALL_S ([\d.]+)", s)
        d = pov.setdefault(int(m.group(1)), {"trace": [], "wall": []})
        if t: d["trace"].append(1000 * float(t.group(1)))
        if w: d["wall"].append(1000 * float(w.group(1)))

cyc = []
p = os.path.join(log, "cycles.log")
if os.path.exists(p):
    cyc = [dict(re.findall(r"(\w+)=(\S+)", l)) for l in open(p) if l.startswith("RESULT")]

osm, covered = [], {}
p = os.path.join(log, "osmesa.log")
if os.path.exists(p):
    for l in open(p):
        kv = dict(re.findall(r"(\w+)=(\S+)", l))
        if l.startswith("RESULT"):
            osm.append(kv)
        elif l.startswith("COVERED") and kv.get("covered"):  # written by run.sh from llvmpipe's image
            covered.setdefault((kv["mesh"], kv["variant"]), set()).add(int(kv["covered"]))

def med(v): return statistics.median(v) if v else float("nan")
def samples(s): return [float(x) for x in s.split(",") if x]

print("| bench | mesh | T | metric | hikari median (min-max) | peer median | hikari/peer | validation hikari / peer |")
print("|---|---|---|---|---|---|---|---|")
for bench in ("B1", "B1p16", "B2"):
    for mesh in ("bunny", "bumpy1m"):
        for t in (1, 2):
            H = [r for r in hik if r.get("bench") == bench and r.get("mesh") == mesh and r.get("threads") == t]
            E = [r for r in emb if r.get("bench") == bench and r.get("mesh") == mesh and int(r.get("threads", 0)) == t]
            if not H: continue
            rays = H[0]["rays"]
            ht = [x for r in H for x in r["trace_samples_ms"]]
            et = [x for r in E for x in samples(r.get("samples_ms", ""))]
            hm, em = rays / med(ht) / 1e3, (E[0] and float(E[0]["rays"]) / med(et) / 1e3) if et else float("nan")
            if bench in ("B1", "B1p16"):
                hv = f'{H[0]["hits"]} / {H[0]["mean_t"]:.6f}'
                ev = f'{E[0]["hits"]} / {E[0]["mean_t"]}' if E else "-"
            else:
                hv = f'{H[0]["occluded"]}'
                ev = f'{round(float(E[0]["frac_occluded"]) * float(E[0]["rays"]))}' if E else "-"
            print(f"| {bench} | {mesh} | {t} | Mrays/s | {hm:.2f} ({rays / max(ht) / 1e3:.2f}-{rays / min(ht) / 1e3:.2f}) | "
                  f"{em:.2f} | {hm / em:.2f} | {hv} vs {ev} |")
            if bench == "B1":
                hb = [x for r in H for x in r["build_samples_ms"]]
                eb = [x for r in E for x in samples(r.get("build_samples_ms", ""))]
                print(f"| build | {mesh} | {t} | ms | {med(hb):.1f} ({min(hb):.1f}-{max(hb):.1f}) | {med(eb):.1f} | "
                      f"{med(eb) / med(hb):.2f} (peer/hikari) | {H[0]['bvh_bytes_per_triangle']} B/tri |")
for t in (1, 2):
    H = [r["wall_ms"] for r in hik if r.get("bench") == "B3" and r.get("threads") == t]
    if not H: continue
    P = pov.get(t, {"trace": [], "wall": []})
    print(f"| B3 | whitted | {t} | hikari process wall vs POV trace, ms | {med(H):.0f} ({min(H)}-{max(H)}) | "
          f"{med(P['trace']):.0f} (wall {med(P['wall']):.0f}) | {med(P['trace']) / med(H):.2f} (peer/hikari) | |")
for t in (1, 2):
    H = [r for r in hik if r.get("bench") == "B5" and r.get("threads") == t]
    if not H: continue
    hm = [x for r in H for x in r["ms_all"]]
    C = [r for r in cyc if r.get("bench") == "B5"] if t == 2 else []
    cm = [x for r in C for x in samples(r.get("samples_ms", ""))]
    img = [r for r in cyc if r.get("bench") == "B5img"]
    hv = "({:.4f}, {:.4f}, {:.4f})".format(*H[-1]["mean_srgb"])
    cv = "({}, {}, {})".format(img[-1]["mean_r"], img[-1]["mean_g"], img[-1]["mean_b"]) if img else "-"
    ratio = f"{med(hm) / med(cm):.2f} (hikari/peer)" if cm else "-"
    print(f"| B5 | cornell | {t} | render wall, ms (64 spp, 8 bounces) | {med(hm):.0f} ({min(hm):.0f}-{max(hm):.0f}) | "
          f"{med(cm):.0f} | {ratio} | mean sRGB {hv} vs {cv} |")

# B4: ms per frame, so the ratios are llvmpipe / hikari (> 1: hikari is faster), against llvmpipe with
# glibc's default malloc and with the SPEC's tuned one (the stronger peer). A hikari line's frame
# times are pooled when it lists them (ms_all or samples_ms), else its median per process is used.
B4_SPEC_COVERED = {"bunny": 389877, "bumpy1m": 357762}
def b4_ms(r):
    for k in ("ms_all", "samples_ms"):
        if isinstance(r.get(k), list) and r[k]: return r[k]
    return [r["ms_per_frame"]]
def spread(v): return f"{med(v):.1f} ({min(v):.1f}-{max(v):.1f})" if v else "-"
def ratio(peer, ours): return f"{med(peer) / med(ours):.2f}" if peer and ours else "-"
b4 = []
for mesh in ("bunny", "bumpy1m"):
    for t in (1, 2):
        for var in ("plain", "shadow"):
            H = [r for r in hik if r.get("bench") == "B4" and r.get("mesh") == mesh and r.get("threads") == t
                 and r.get("variant") == var]
            L = {mal: [x for r in osm if r.get("mesh") == mesh and r.get("variant") == var
                       and r.get("lp_threads") == str(t) and r.get("malloc") == mal
                       for x in samples(r.get("samples_ms", ""))] for mal in ("default", "tuned")}
            if not H and not L["default"] and not L["tuned"]: continue
            hm = [x for r in H for x in b4_ms(r)]
            # Per-process medians only: the range is the fastest and slowest frame the lines report.
            lo = min([r.get("ms_min", min(b4_ms(r))) for r in H], default=0)
            hi = max([r.get("ms_max", max(b4_ms(r))) for r in H], default=0)
            hs = f"{med(hm):.1f} ({lo:.1f}-{hi:.1f})" if hm else "-"
            hc = ",".join(str(c) for c in sorted({r["covered_pixels"] for r in H if "covered_pixels" in r})) or "-"
            lc = ",".join(str(c) for c in sorted(covered.get((mesh, var), ()))) or "-"
            b4.append(f"| B4 | {mesh} | {t} | {var} | {hs} | {spread(L['default'])} | {spread(L['tuned'])} | "
                      f"{ratio(L['default'], hm)} | {ratio(L['tuned'], hm)} | {hc} / {lc} (SPEC {B4_SPEC_COVERED[mesh]}) |")
if b4:
    print("\n| bench | mesh | T | variant | hikari ms/frame median (min-max) | llvmpipe default malloc | "
          "llvmpipe tuned malloc | llvmpipe/hikari default | llvmpipe/hikari tuned | covered pixels hikari / llvmpipe |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(b4))
p = os.path.join(log, "psnr.txt")
if os.path.exists(p):
    print("\n" + open(p).read().strip())
