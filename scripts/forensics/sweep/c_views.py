"""Task C(4): the drawing cameras of the four pictures (scale and view direction), the image planes."""
import numpy as np
fit = np.load("c_fit.npy", allow_pickle=True).item()
for k, v in fit.items():
    M = v["M"]; s = np.sqrt(np.mean(np.diag(M @ M.T))); r1, r2 = M/s
    w = np.cross(r1, r2)
    el = np.degrees(np.arcsin(w[2])); az = np.degrees(np.arctan2(w[1], w[0]))
    print(f"picture {k+1}: scale {s:.5f} (x 3 cm) per unit, view direction {np.round(w, 4)} "
          f"(azimuth {az:.1f} deg, elevation {el:.1f} deg); frame-2 rays phi {np.degrees(v['phi']) % 180:.3f} deg, "
          f"|image plane offset| {abs(v['h']):.3f}; body shown: {v['shown']}; labels primed: {v['primed']}")
