#!/usr/bin/env python3
"""Annual daylight metrics from per-source contributions (examples/annual/README.md).

  annual.py sources [--lat 47 --lon 8 --meridian 15]      > sources.rad  (+ mods.txt)
  annual.py sensors                                        > sensors.txt
  annual.py metrics coef.txt [weather.epw]                 -> metrics.txt, da300.png

`sources` writes one distant light source of unit radiance per sun position (hourly on
the 21st of seven months whose declinations cover the year) and per Tregenza sky patch,
plus one for the ground, each with its own modifier (listed in mods.txt for rcontrib -M).
`metrics` reads rcontrib's -V- output (one line per sensor, one RGB triple per modifier
in mods.txt order), builds every daylit hour's illuminance as a weighted sum of the
columns (sun: the nearest sun position times DNI over the sun's solid angle; sky patches:
a CIE overcast distribution scaled to the diffuse horizontal irradiance; ground: 20 %
of the global horizontal irradiance) and prints daylight autonomy at 300 lx and useful
daylight illuminance (100-2000 lx) over occupied hours (8-18 h), with a false-colour
picture of the grid. Without an EPW file it uses a synthetic year (clear-sky irradiance
dimmed by a repeatable day-by-day cloud series); with one it takes DNI and DHI from it.
Standard library only.
"""
import math
import struct
import sys
import zlib

SUN_OMEGA_DEG = 0.533             # the sun's diameter
MONTH_DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
SUN_DAYS = [(12, 21), (1, 21), (2, 21), (3, 21), (4, 21), (5, 21), (6, 21)]
TREGENZA = [(0, 12, 30), (12, 24, 30), (24, 36, 24), (36, 48, 24), (48, 60, 18),
            (60, 72, 12), (72, 84, 6), (84, 90, 1)]   # altitude band, patches
LUMINOUS_EFFICACY = 179.0         # RADIANCE's lm/W for its white light
GROUND_REFLECTANCE = 0.2
OCCUPIED = range(8, 18)           # local standard time, hour starting


def sun_position(day_of_year, hour, lat, lon, meridian):
    """Solar altitude and azimuth (degrees, azimuth clockwise from north) at local
    standard time `hour` (fractional), Spencer's declination and equation of time."""
    g = 2 * math.pi * (day_of_year - 1) / 365
    decl = (0.006918 - 0.399912 * math.cos(g) + 0.070257 * math.sin(g)
            - 0.006758 * math.cos(2 * g) + 0.000907 * math.sin(2 * g)
            - 0.002697 * math.cos(3 * g) + 0.00148 * math.sin(3 * g))
    eot = 229.18 * (0.000075 + 0.001868 * math.cos(g) - 0.032077 * math.sin(g)
                    - 0.014615 * math.cos(2 * g) - 0.040849 * math.sin(2 * g))  # minutes
    solar = hour + (4 * (lon - meridian) + eot) / 60
    ha = math.radians(15 * (solar - 12))
    phi = math.radians(lat)
    sin_alt = math.sin(phi) * math.sin(decl) + math.cos(phi) * math.cos(decl) * math.cos(ha)
    alt = math.asin(max(-1, min(1, sin_alt)))
    az = math.atan2(math.sin(ha), math.cos(ha) * math.sin(phi) - math.tan(decl) * math.cos(phi))
    return math.degrees(alt), (math.degrees(az) + 180) % 360


def direction(alt, az):
    a, z = math.radians(alt), math.radians(az)
    return (math.cos(a) * math.sin(z), math.cos(a) * math.cos(z), math.sin(a))


def day_of_year(month, day):
    return sum(MONTH_DAYS[:month - 1]) + day


def sky_patches():
    """(altitude, azimuth, solid angle) of the 145 Tregenza patch centres."""
    out = []
    for a1, a2, n in TREGENZA:
        for k in range(n):
            omega = 2 * math.pi / n * (math.sin(math.radians(a2)) - math.sin(math.radians(a1)))
            alt = 90.0 if n == 1 else (a1 + a2) / 2
            out.append((alt, 360.0 * k / n, omega))
    return out


def sun_positions(lat, lon, meridian):
    out = []
    for month, day in SUN_DAYS:
        for hour in range(4, 21):
            alt, az = sun_position(day_of_year(month, day), hour + 0.5, lat, lon, meridian)
            if alt > 2:
                out.append((alt, az))
    return out


def write_sources(lat, lon, meridian):
    suns = sun_positions(lat, lon, meridian)
    mods = []
    print(f"# Sources for annual.py metrics: {len(suns)} sun positions ({lat} N, {lon} E),")
    print("# 145 Tregenza sky patches and the ground, each a distant light of radiance 1.")
    for i, (alt, az) in enumerate(suns):
        d = direction(alt, az)
        name = f"sun{i:03d}"
        mods.append(name)
        print(f"# sun {i}: altitude {alt:.2f} azimuth {az:.2f}")
        print(f"void light {name} 0 0 3 1 1 1")
        print(f"{name} source {name}_disk 0 0 4 {d[0]:.6f} {d[1]:.6f} {d[2]:.6f} {SUN_OMEGA_DEG}")
    for i, (alt, az, omega) in enumerate(sky_patches()):
        d = direction(alt, az)
        # A cone of the patch's solid angle: 2 pi (1 - cos(a/2)) = omega.
        angle = 2 * math.degrees(math.acos(1 - omega / (2 * math.pi)))
        name = f"sky{i + 1:03d}"
        mods.append(name)
        print(f"void light {name} 0 0 3 1 1 1")
        print(f"{name} source {name}_patch 0 0 4 {d[0]:.6f} {d[1]:.6f} {d[2]:.6f} {angle:.4f}")
    mods.append("ground")
    print("void light ground 0 0 3 1 1 1")
    print("ground source ground_dome 0 0 4 0 0 -1 180")
    with open("mods.txt", "w") as f:
        f.write("\n".join(mods) + "\n")


def write_sensors():
    for j in range(8):
        for i in range(12):
            print(f"{0.25 + 0.5 * i:.2f} {0.25 + 0.5 * j:.2f} 0.8 0 0 1")


def synthetic_weather(lat, lon, meridian):
    """(month, day, hour, DNI, DHI) for 8760 hours: a clear-sky model dimmed by a
    repeatable series of daily cloud covers."""
    seed = 12345
    hours = []
    doy = 0
    for month in range(1, 13):
        for day in range(1, MONTH_DAYS[month - 1] + 1):
            doy += 1
            seed = (1103515245 * seed + 12345) % 2**31
            cloud = (seed / 2**31) ** 0.7
            for hour in range(24):
                alt, _ = sun_position(doy, hour + 0.5, lat, lon, meridian)
                if alt <= 0:
                    hours.append((month, day, hour, 0.0, 0.0))
                    continue
                s = math.sin(math.radians(alt))
                dni = 950 * math.exp(-0.14 / max(s, 0.03)) * (1 - 0.95 * cloud)
                dhi = (40 + 110 * cloud) * s ** 0.8 + 20 * s
                hours.append((month, day, hour, dni, dhi))
    return hours


def epw_weather(path):
    hours = []
    with open(path, encoding="latin-1") as f:
        for k, line in enumerate(f):
            if k < 8:
                continue  # EPW header lines
            v = line.split(",")
            # EPW hours run 1..24 and end at the hour: hour 1 is 0:00-1:00.
            hours.append((int(v[1]), int(v[2]), int(v[3]) - 1, float(v[14]), float(v[15])))
    return hours


def read_coefficients(path):
    rows = []
    with open(path) as f:
        for line in f:
            v = line.split()
            if not v or not v[0][0] in "0123456789-.":
                continue  # header lines, if rcontrib ran without -h
            rows.append([0.265 * float(v[3 * k]) + 0.670 * float(v[3 * k + 1])
                         + 0.065 * float(v[3 * k + 2]) for k in range(len(v) // 3)])
    return rows


def colour(t):
    """A blue-to-red ramp like falsecolor's default palette, t in [0, 1]."""
    stops = [(0.0, (0, 0, 130)), (0.25, (0, 120, 255)), (0.5, (60, 200, 80)),
             (0.75, (250, 220, 0)), (1.0, (220, 30, 0))]
    t = max(0.0, min(1.0, t))
    for (t0, c0), (t1, c1) in zip(stops, stops[1:]):
        if t <= t1:
            f = (t - t0) / (t1 - t0)
            return tuple(int(c0[i] + f * (c1[i] - c0[i])) for i in range(3))
    return stops[-1][1]


def write_png(path, width, height, pixel):
    raw = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def picture(path, values, cols, rows):
    """The grid (north up) at 40 px per sensor, with a legend bar 0..100 % below it."""
    cell, bar = 40, 24
    w, h = cols * cell, rows * cell + bar

    def pixel(x, y):
        if y >= rows * cell:
            t = x / (w - 1)
            return (255, 255, 255) if y < rows * cell + 4 else colour(t)
        i, j = x // cell, rows - 1 - y // cell
        return colour(values[j * cols + i] / 100)
    write_png(path, w, h, pixel)


def metrics(coef_path, epw=None, lat=47.0, lon=8.0, meridian=15.0):
    rows = read_coefficients(coef_path)
    suns = sun_positions(lat, lon, meridian)
    patches = sky_patches()
    nsun = len(suns)
    if rows and len(rows[0]) != nsun + len(patches) + 1:
        sys.exit(f"annual.py: {coef_path}: {len(rows[0])} columns, expected {nsun + len(patches) + 1}")
    sun_dirs = [direction(a, z) for a, z in suns]
    sun_omega = 2 * math.pi * (1 - math.cos(math.radians(SUN_OMEGA_DEG / 2)))
    weather = epw_weather(epw) if epw else synthetic_weather(lat, lon, meridian)
    n = len(rows)
    above300 = [0] * n
    udi = [[0, 0, 0] for _ in range(n)]  # below 100, 100-2000, above 2000
    occupied = 0
    doy = 0
    last = None
    for month, day, hour, dni, dhi in weather:
        if (month, day) != last:
            doy, last = doy + 1, (month, day)
        if hour not in OCCUPIED:
            continue
        occupied += 1
        alt, az = sun_position(doy, hour + 0.5, lat, lon, meridian)
        weights = [0.0] * len(rows[0])
        if alt > 0 and dni > 0:
            d = direction(alt, az)
            k = max(range(nsun), key=lambda i: sum(a * b for a, b in zip(d, sun_dirs[i])))
            weights[k] = dni / sun_omega
        if dhi > 0:
            zenith = dhi / (7 * math.pi / 9)   # CIE overcast: E_h = 7 pi / 9 L_z
            for p, (palt, _, _) in enumerate(patches):
                weights[nsun + p] = zenith * (1 + 2 * math.sin(math.radians(palt))) / 3
        ghi = dhi + dni * max(0.0, math.sin(math.radians(alt)))
        weights[-1] = GROUND_REFLECTANCE * ghi / math.pi
        for s, row in enumerate(rows):
            lux = LUMINOUS_EFFICACY * sum(w * c for w, c in zip(weights, row) if w)
            above300[s] += lux >= 300
            udi[s][0 if lux < 100 else 1 if lux <= 2000 else 2] += 1
    da = [100.0 * a / occupied for a in above300]
    with open("metrics.txt", "w") as f:
        f.write("# x y DA300[%] UDI<100[%] UDI100-2000[%] UDI>2000[%]\n")
        for s in range(n):
            x, y = 0.25 + 0.5 * (s % 12), 0.25 + 0.5 * (s // 12)
            u = [100.0 * v / occupied for v in udi[s]]
            f.write(f"{x:.2f} {y:.2f} {da[s]:.1f} {u[0]:.1f} {u[1]:.1f} {u[2]:.1f}\n")
    mean = lambda v: sum(v) / len(v)
    print(f"{occupied} occupied hours, {n} sensors")
    print(f"daylight autonomy (300 lx): mean {mean(da):.1f} %, "
          f"sensors above 50 %: {100.0 * sum(d >= 50 for d in da) / n:.0f} %")
    print("useful daylight illuminance: below 100 lx {:.1f} %, 100-2000 lx {:.1f} %, "
          "above 2000 lx {:.1f} %".format(*(mean([100.0 * u[k] / occupied for u in udi]) for k in range(3))))
    if n == 96:
        picture("da300.png", da, 12, 8)


def main(argv):
    if len(argv) >= 2 and argv[1] == "sources":
        write_sources(47.0, 8.0, 15.0)
    elif len(argv) >= 2 and argv[1] == "sensors":
        write_sensors()
    elif len(argv) >= 3 and argv[1] == "metrics":
        metrics(argv[2], argv[3] if len(argv) > 3 else None)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
