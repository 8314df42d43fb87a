#!/usr/bin/env python3
"""A stand-in DEM of the simulated pit (benches of 10 m, 60 m deep, the haul ramp's slope north to south) for
the 3D screenshots until the simulated site ships its own pit_dem.tif. Writes an ESRI ASCII grid in
WGS84 degrees around the built-in site origin; convert with
  gdal_translate -a_srs EPSG:4326 pit.asc pit_dem.tif
Usage: demo-pit-dem.py OUT.asc [LAT LON ALT]"""
import math
import sys

out = sys.argv[1]
lat0, lon0, alt0 = (float(v) for v in sys.argv[2:5]) if len(sys.argv) >= 5 else (48.2085, 11.4702, 480.0)
cell = 2e-5
me = 111320.0 * math.cos(math.radians(lat0))
mn = 110574.0
cols, rows = int(1600 / me / cell), int(1700 / mn / cell)
west, south = lon0 - cols * cell / 2, lat0 - rows * cell / 2 - 100 / mn


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def height(e, n):
    # Down the ramp from the hub (n = 200, 0 m) to the pit floor (n = -300, -60 m), flat floor to the
    # south wall, walls east and west; in 10 m benches with short faces.
    depth = 60.0 * clamp((200.0 - n) / 500.0, 0.0, 1.0)
    depth *= clamp((400.0 - abs(e)) / 120.0, 0.0, 1.0) * clamp((n + 640.0) / 120.0, 0.0, 1.0)
    bench, frac = divmod(depth, 10.0)
    return alt0 - (bench * 10.0 + 10.0 * clamp((frac - 7.0) / 3.0, 0.0, 1.0))


with open(out, "w") as f:
    f.write(f"ncols {cols}\nnrows {rows}\nxllcorner {west:.9f}\nyllcorner {south:.9f}\ncellsize {cell}\n"
            "NODATA_value -9999\n")
    for r in range(rows):
        lat = south + (rows - r - 0.5) * cell
        n = (lat - lat0) * mn
        f.write(" ".join(f"{height((west + (c + 0.5) * cell - lon0) * me, n):.2f}" for c in range(cols)))
        f.write("\n")
