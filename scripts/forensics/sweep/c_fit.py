"""Task C: reconstruct each of the four oblique drawings of section 5.1.
Drawing model: image = c + M X (+ (0.03,0.03) for a label), c = centre of the drawn cube, M a 2x3
linear map fixed by the cube [-10,10]^3 (edges from the hidden corner = 20*M e_k, the axis labelled
x/y/z by the label placed at an edge midpoint + 0.03); the edge signs are chosen by the printed
coordinates of the points drawn (P, Q, R or P, Q', R')."""
import itertools, numpy as np
from scipy.optimize import least_squares
from c_parse import pictures
OFF = np.array([0.03, 0.03])
Pp = np.zeros(3); Qp = np.array([3.46537, 2, -2]); Rp = np.array([.68697, 5, 4])
Qq = np.array([4.63902, 2, -2]); Rq = np.array([4.37296, 5, 4])
pics = pictures()

def camera(pic, pts3d):
    thin = pic["thin"]; A = thin[0][0]
    E = [s[1] - s[0] for s in thin]                      # three edges from the hidden corner
    corners = [A + sum(E[i] for i in S) for r in range(4) for S in itertools.combinations(range(3), r)]
    c = np.mean(corners, axis=0)
    # which edge is x, y, z: the label sits at the midpoint (+0.03) of some edge parallel to E[i]
    axis_of = {}
    for lab in "xyz":
        p = pic["labels"][lab][0] - OFF; best = None
        for i in range(3):
            for S in itertools.chain.from_iterable(itertools.combinations([j for j in range(3) if j != i], r) for r in range(3)):
                mid = A + sum(E[j] for j in S) + E[i]/2
                d = np.linalg.norm(mid - p)
                if best is None or d < best[0]: best = (d, i)
        axis_of[lab] = best[1]
    cols = [E[axis_of[l]]/20 for l in "xyz"]
    best = None
    for sg in itertools.product((1, -1), repeat=3):
        M = np.array([s*v for s, v in zip(sg, cols)]).T
        err = sum(np.linalg.norm(c + M@X + OFF - pic["labels"][n][0]) for n, X in pts3d.items())
        if best is None or err < best[0]: best = (err, M)
    return c, best[1], axis_of

def img(c, M, X, label=False): return c + M@X + (OFF if label else 0)

out = {}
for k, pic in enumerate(pics):
    lab = pic["labels"]
    primed = "Q'" in lab
    qn, rn = ("Q'", "R'") if primed else ("Q", "R")
    # which body do the label positions show?  try both (the original P,Q,R and the rotated P,Q',R')
    fits = []
    for bname, (QQ, RR) in (("original", (Qp, Rp)), ("rotated", (Qq, Rq))):
        c, M, ax = camera(pic, {"P": Pp, qn: QQ, rn: RR})
        e = np.linalg.norm(img(c, M, QQ, True) - lab[qn][0]) + np.linalg.norm(img(c, M, RR, True) - lab[rn][0])
        fits.append((e, bname, c, M, QQ, RR))
        print(f"   [picture {k+1}] labels {qn},{rn} vs {bname} body: label misfit {e*1000:.2f}e-3")
    e, shown, c, M, QS, RS = min(fits, key=lambda t: t[0])
    print(f"   [picture {k+1}] -> shows the {shown} body")
    # view direction of the drawing: M = s * (first two rows of a rotation)?
    G = M @ M.T
    print(f"\n=== picture {k+1} (line {pic['start']}), labels {'primed' if primed else 'unprimed'}; centre {np.round(c, 4)}")
    print("   M =", np.round(M, 5).tolist(), " M M^T =", np.round(G, 6).tolist())
    # 1) the body points: solve x for Q/R (y, z as printed) from the label
    for nm in (["Q'", "R'"] if primed else ["Q", "R"]):
        Y = (QS if nm.startswith("Q") else RS).copy()
        f = lambda x: img(c, M, np.array([x[0], Y[1], Y[2]]), True) - lab[nm][0]
        r = least_squares(f, [Y[0]])
        print(f"   {nm}: x from label = {r.x[0]:.3f} (residual {np.linalg.norm(r.fun)*1000:.1f} mu-units); "
              f"printed Q/R x = {Y[0]}, Q'/R' x = {(Qq if nm.startswith('Q') else Rq)[0]}")
    # 2) n: direction of its segment
    nseg = [s for s in pic["segs"] if s[2] in (800, 900, 1040, 1140)][0]
    d = nseg[1] - nseg[0]
    # solve the 3-D direction in the plane x=0 (n is orthogonal to the frame-1 rays, which are along x)
    f = lambda t: M @ np.array([0, np.sin(t[0]), np.cos(t[0])])*t[1] - d
    r = least_squares(f, [0.0, -20]); nvec = np.array([0, np.sin(r.x[0]), np.cos(r.x[0])])
    print(f"   n segment {np.round(nseg[0], 3)}->{np.round(nseg[1], 3)}: 3-D direction (0, {nvec[1]:.4f}, {nvec[2]:.4f}), "
          f"drawn length {abs(r.x[1]):.3f} (cube edge 20); residual {np.linalg.norm(r.fun)*1000:.2f}e-3")
    # 3) frame-1 image plane: x of P1, Q1, R1 (y, z of P, Q, R)
    xs = []
    for nm, Y in (("P1", Pp), ("Q1", Qp), ("R1", Rp)):
        f = lambda x: img(c, M, np.array([x[0], Y[1], Y[2]]), True) - lab[nm][0]
        r = least_squares(f, [10.0]); xs.append(r.x[0])
    print("   P1, Q1, R1: x =", np.round(xs, 3))
    # 4) frame-2 rays: P2, Q2, R2 = X + s_X u, u = (cos phi, sin phi, 0) [n = z], u.(X2) = h
    names = ["P2'", "Q2'", "R2'"] if primed else ["P2", "Q2", "R2"]
    body = [Pp, QS, RS]
    def res(p):
        phi, h = p; u = np.array([np.cos(phi), np.sin(phi), 0])
        return np.concatenate([img(c, M, X + (h - u@X)*u, True) - lab[nm][0] for nm, X in zip(names, body)])
    best = min((least_squares(res, [p0, 5.0]) for p0 in np.linspace(-np.pi, np.pi, 13)), key=lambda r: r.cost)
    phi, h = best.x
    print(f"   frame-2 ray direction u = (cos, sin, 0) at phi = {np.degrees(phi):.3f} deg, image plane u.X = {h:.3f}; "
          f"label residual rms {np.sqrt(np.mean(best.fun**2))*1000:.2f}e-3")
    out[k] = dict(c=c, M=M, phi=phi, h=h, primed=primed, shown=shown)
    # 5) check the drawn ray segments p2 q2 r2 against the model
    segs = [s for s in pic["segs"] if s[2] in {812, 815, 818, 912, 915, 918, 1052, 1055, 1058, 1152, 1155, 1158}]
    u = np.array([np.cos(phi), np.sin(phi), 0])
    for s, X in zip(segs, body):
        X2 = X + (h - u@X)*u
        a = img(c, M, X2); b = s[1]
        # other end: X2 - t u
        t = least_squares(lambda t: img(c, M, X2 - t[0]*u) - b, [10.0])
        print(f"      ray segment line {s[2]}: start {np.round(s[0], 3)} vs model {np.round(a, 3)}; end at t = {t.x[0]:.3f} "
              f"(residual {np.linalg.norm(t.fun)*1000:.2f}e-3)")
np.save("c_fit.npy", out, allow_pickle=True)
