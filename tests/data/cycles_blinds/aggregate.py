#!/usr/bin/env python3
"""Combine the JSON-lines output of render_irradiance.py into NAME.txt (81 lines:
mean irradiance W/m2 over the repeats, standard error of that mean = sample standard
deviation of the repeats / sqrt(number of repeats)).

    python3 aggregate.py RUNDIR NAME [NAME ...]      # reads RUNDIR/NAME.jsonl

Also prints, per file, the mean over sensors with its standard error, the largest
relative standard error, and a cross-check of the standard error estimated from the
spread of the individual pixels (each pixel is an independent estimate)."""
import json, math, sys

rundir = sys.argv[1]
for name in sys.argv[2:]:
    per = {}
    pix = {}
    with open('%s/%s.jsonl' % (rundir, name)) as f:
        for line in f:
            r = json.loads(line)
            per.setdefault(r['sensor'], {})[r['rep']] = r['E']
            pix.setdefault(r['sensor'], []).extend(r['pix'])
    n_s = len(per)
    nreps = sorted(set(len(v) for v in per.values()))
    rows, reps_mean = [], {}
    worst, worst_pix_ratio = (0, None), []
    for i in range(n_s):
        v = list(per[i].values())
        n = len(v)
        m = sum(v) / n
        sd = math.sqrt(sum((x - m) ** 2 for x in v) / (n - 1)) if n > 1 else float('nan')
        se = sd / math.sqrt(n)
        p = pix[i]
        pm = sum(p) / len(p)
        pse = math.sqrt(sum((x - pm) ** 2 for x in p) / (len(p) - 1) / len(p))
        rows.append((m, se, pse))
        if m > 0 and se / m > worst[0]:
            worst = (se / m, i)
        for rep, x in per[i].items():
            reps_mean.setdefault(rep, []).append(x)
    with open('%s.txt' % name, 'w') as f:
        for m, se, _ in rows:
            f.write('%.6g %.3g\n' % (m, se))
    # mean over the 80 work-plane sensors; SE from the per-repeat means
    rm = [sum(v[:80]) / 80 for v in reps_mean.values() if len(v) == n_s]
    M = sum(rm) / len(rm)
    MSE = math.sqrt(sum((x - M) ** 2 for x in rm) / (len(rm) - 1) / len(rm)) if len(rm) > 1 else float('nan')
    ratios = [r[1] / r[2] for r in rows if r[2] > 0]
    print('%s: sensors %d, repeats %s, mean(80) %.4f +- %.4f (%.3f%%), ceiling %.4f +- %.4f, '
          'max rel SE %.3f%% (sensor %s), SE(repeats)/SE(pixels) median %.2f'
          % (name, n_s, nreps, M, MSE, 100 * MSE / M if M else 0, rows[80][0], rows[80][1],
             100 * worst[0], worst[1], sorted(ratios)[len(ratios) // 2] if ratios else float('nan')))
