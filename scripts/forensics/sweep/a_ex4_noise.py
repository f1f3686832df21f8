"""Task A: relative errors of section 4's 1% run (lines 686-691), squared values vs lengths."""
import numpy as np
xt = np.array([4, 9, 12.6878, 50, 55.25, 33.9578])
for name, x in (("0.1% run (676-681)", [4.00643, 9.16415, 12.8076, 50.6951, 56.0627, 34.4038]),
                ("1% run (686-691)", [4.09934, 11.2053, 14.2781, 58.6152, 65.3898, 39.4439])):
    x = np.array(x)
    print(name, "x rel err %:", np.round(100*(x/xt-1), 2), " length rel err %:", np.round(100*(np.sqrt(x/xt)-1), 2),
          " mean length err %:", round(100*np.mean(np.abs(np.sqrt(x/xt)-1)), 2))
