"""Exit 0 when two netCDF files hold the same variables with the same values to the last bit
(NaN equal to NaN, fill values equal), else print each difference and exit 1."""
import sys

import netCDF4
import numpy as np

a, b = (netCDF4.Dataset(path) for path in sys.argv[1:3])
differences = []
for name in sorted(set(a.variables) | set(b.variables)):
    if name not in a.variables or name not in b.variables:
        differences.append(f"{name}: only in one file")
        continue
    x, y = a.variables[name][:], b.variables[name][:]
    if x.shape != y.shape or x.dtype != y.dtype:
        differences.append(f"{name}: shape {x.shape} {x.dtype} against {y.shape} {y.dtype}")
    elif not np.array_equal(np.ma.getmaskarray(x), np.ma.getmaskarray(y)):
        differences.append(f"{name}: different fill")
    elif x.dtype.kind == "f":
        xs, ys = np.ma.filled(x, 0.0), np.ma.filled(y, 0.0)
        if not np.array_equal(xs.view(np.uint64 if xs.itemsize == 8 else np.uint32),
                              ys.view(np.uint64 if ys.itemsize == 8 else np.uint32)):
            differences.append(f"{name}: largest difference {np.max(np.abs(xs - ys))}")
    elif not np.array_equal(np.ma.filled(x), np.ma.filled(y)):
        differences.append(f"{name}: values differ")
for d in differences:
    print(d)
print(f"{len(a.variables)} variables, {len(differences)} differ")
sys.exit(1 if differences else 0)
