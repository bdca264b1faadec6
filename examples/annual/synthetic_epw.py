#!/usr/bin/env python3
"""A synthetic weather year for Zurich in EnergyPlus (EPW) layout, for when no real
weather file is at hand: a clear-sky model of direct normal and diffuse horizontal
irradiance, dimmed by a repeatable day-by-day cloud cover (a seeded LCG). Nothing in it
comes from measured weather; give a real EPW file to run.sh for a real climate.

    python3 synthetic_epw.py > zurich.epw
"""
import math
import sys

LAT, LON, TZ, ELEV = 47.38, 8.54, 1.0, 413.0  # EPW: east longitude and zone positive
MONTH_DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]


def sun_altitude(doy, hour):
    """Solar altitude in degrees at local standard time `hour` (hours, 0-24)."""
    decl = 23.45 * math.sin(math.radians(360 * (284 + doy) / 365))
    b = math.radians(360 * (doy - 81) / 364)
    eot = 9.87 * math.sin(2 * b) - 7.53 * math.cos(b) - 1.5 * math.sin(b)  # minutes
    solar = hour + (4 * (LON - 15 * TZ) + eot) / 60
    ha = math.radians(15 * (solar - 12))
    lat, d = math.radians(LAT), math.radians(decl)
    s = math.sin(lat) * math.sin(d) + math.cos(lat) * math.cos(d) * math.cos(ha)
    return math.degrees(math.asin(max(-1.0, min(1.0, s))))


def header():
    return [
        f"LOCATION,Zurich (synthetic),ZH,CHE,radphoton,066600,{LAT},{LON},{TZ},{ELEV}",
        "DESIGN CONDITIONS,0",
        "TYPICAL/EXTREME PERIODS,0",
        "GROUND TEMPERATURES,0",
        "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0",
        "COMMENTS 1,Synthetic year: clear-sky model dimmed by a seeded daily cloud cover",
        "COMMENTS 2,Not measured weather",
        "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31",
    ]


def record(month, day, hour, dni, dhi):
    # 35 fields: year month day hour minute source, dry bulb .. pressure, radiation
    # (ext horizontal, ext normal, horizontal IR, GHI, DNI, DHI, illuminances ..), then
    # wind, sky cover and the rest as typical placeholders.
    ghi = dhi + dni * max(0.0, math.sin(math.radians(sun_altitude(doy_of(month, day), hour - 0.5))))
    fields = [2021, month, day, hour, 60, "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9*9*9",
              10.0, 5.0, 70, 96500, 0, 0, 300, round(ghi), round(dni), round(dhi),
              0, 0, 0, 0, 180, 2.0, 5, 5, 20.0, 77777, 9, 999999999, 10, 0.1, 0, 88,
              0.2, 0, 1.0]
    return ",".join(str(f) for f in fields)


def doy_of(month, day):
    return sum(MONTH_DAYS[: month - 1]) + day


def main():
    out = header()
    seed = 12345
    for month in range(1, 13):
        for day in range(1, MONTH_DAYS[month - 1] + 1):
            seed = (1103515245 * seed + 12345) % 2**31
            cloud = (seed / 2**31) ** 0.7
            for hour in range(1, 25):  # EPW hour h covers h-1 .. h
                alt = sun_altitude(doy_of(month, day), hour - 0.5)
                dni = dhi = 0.0
                if alt > 0:
                    s = math.sin(math.radians(alt))
                    dni = 950 * math.exp(-0.14 / max(s, 0.03)) * (1 - 0.95 * cloud)
                    dhi = (40 + 110 * cloud) * s**0.8 + 20 * s
                out.append(record(month, day, hour, dni, dhi))
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
