"""Task C(3): the member through its images.  Frame 1 (rays along x) sees (y, z); frame 2 (rays
along u = (cos phi, sin phi, 0)) sees (X.e, z) with e = (sin phi, -cos phi, 0).  The printed points give
frame-1 images Q1 = (2,-2), R1 = (5,4) and frame-2 images Q2 = (4,-2), R2 = (3,4) (integers); each point
then fixes phi by itself: X_x = (w + y cos phi)/sin phi with w its frame-2 abscissa.
The agreement of the angles from Q and from R (and from Q', R') measures the printed digits."""
import numpy as np
from scipy.optimize import brentq
pts = {"Q": (3.46537, 2, 4), "R": (.68697, 5, 3), "Q'": (4.63902, 2, 4), "R'": (4.37296, 5, 3)}
def angles(x, y, w):
    """all roots in (0, 180) deg; the amplitude sqrt(x^2+y^2) vs w shows the conditioning"""
    f = lambda p: x*np.sin(p) - y*np.cos(p) - w
    g = np.radians(np.linspace(0.01, 179.99, 20000)); v = f(g)
    r = [np.degrees(brentq(f, g[i], g[i+1])) for i in range(len(g)-1) if v[i]*v[i+1] < 0]
    return r, np.hypot(x, y)
allr = {}
for k, v in pts.items():
    r, amp = angles(*v); allr[k] = r
    print(f"  {k}: roots phi = {np.round(r, 4)} deg; |X_xy| = {amp:.5f} vs frame-2 abscissa {v[2]}"
          f"  (d phi / d x = {1/np.sqrt(max(amp**2 - v[2]**2, 1e-30)):.2f} rad per unit if near-tangent)")
ref = {"Q": 118.65, "R": 118.65, "Q'": 75.7, "R'": 75.7}
phi = {k: min(allr[k], key=lambda t: abs(t - ref[k])) if allr[k] else np.nan for k in pts}
print("view angle of frame 2 from each point (deg), nearest the figure's:", {k: round(v, 5) for k, v in phi.items()})
ph, php = (phi["Q"]+phi["R"])/2, (phi["Q'"]+phi["R'"])/2
print(f"original member phi = {ph:.5f} (Q/R disagree by {phi['Q']-phi['R']:+.5f}); rotated phi' = {php:.5f} "
      f"(disagree {phi[chr(81)+chr(39)]-phi[chr(82)+chr(39)]:+.5f}); theta = {php-ph:.5f} deg")
for k, (x, y, w) in pts.items():
    p = np.radians(ph if k in ("Q", "R") else php)
    print(f"  {k}: frame-2 abscissa at the common angle {x*np.sin(p) - y*np.cos(p):.6f} (integer {w}); "
          f"x rebuilt {(w + y*np.cos(p))/np.sin(p):.5f} vs printed {x}")
# rebuild Q', R' from P, Q, R alone: phi from Q and R (mean), theta from the figure (-42.93) or exact
for th in (-42.931, php - ph):
    p2 = np.radians(ph + th)
    print(f"  theta = {th:.4f}: Q'x = {(4 + 2*np.cos(p2))/np.sin(p2):.5f}, R'x = {(3 + 5*np.cos(p2))/np.sin(p2):.5f}")
# the drawing: the frame-2 image plane sits at u.X = 7 in both figures, frame 1's at x = 10
