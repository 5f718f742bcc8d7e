#!/usr/bin/env python3
"""The equation-of-state figure of docs/PHYSICS.md (issue 15), as SVG, with no dependency
beyond the Python standard library.

    scripts/physics-plot.py OUT.svg RUN.tsv [RUN.tsv ...]

Each RUN.tsv is the output of `physics_eos eos` (tests/physics_eos.c): tab-separated lines
N, eta, Z, Z_err, Z_err_B/2, ... ('#' lines are headers). The figure has two panels:
  top:    Z(eta) measured (one marker per N) against Henderson (1975), Kolafa and Rottner (2006,
          the rho_max = 0.90 fit, drawn up to its end at eta = 0.7069) and the liquid-hexatic
          coexistence pressure of Engel et al. (2013), beta P sigma^2 = 9.185 for 0.700-0.716;
  bottom: the deviation from Kolafa and Rottner in per cent, with the error bars (the larger of
          the two block estimates) and Henderson's deviation for scale.
The literature formulas are the ones tests/physics_eos.c uses; docs/PHYSICS.md cites them.
"""
import math
import sys

KR = [(0, 1.0), (1, 2.0), (2, 1.12801775), (3, 0.00181895291), (4, -0.0526134737), (5, 0.0504960168),
      (6, -0.0325537792), (7, 0.0134578632), (8, 0.00140888182), (9, -0.00834273601), (10, 0.00694127367),
      (11, -0.00262254723), (12, 0.000355746352), (22, -5.24672938e-9), (57, 5.88054639e-23)]
ETA_KR_MAX = 0.90 * math.pi / 4.0


def z_kr(eta):
    x = eta / (1.0 - eta)
    return sum(a * x ** p for p, a in KR)


def z_h(eta):
    return (1.0 + eta * eta / 8.0) / (1.0 - eta) ** 2


def z_engel(eta):
    return 9.185 * math.pi / (4.0 * eta)


def read_runs(paths):
    pts = []
    for p in paths:
        with open(p) as f:
            for line in f:
                if not line.strip() or line.startswith("#"):
                    continue
                c = line.split("\t")
                n, eta, z, e1, e2 = int(c[0]), float(c[1]), float(c[2]), float(c[3]), float(c[4])
                err = max(e1, e2) if e2 == e2 else e1
                pts.append((n, eta, z, err))
    return pts


class Panel:
    """A rectangle of the SVG with linear axes."""

    def __init__(self, x0, y0, w, h, xr, yr):
        self.x0, self.y0, self.w, self.h, self.xr, self.yr = x0, y0, w, h, xr, yr

    def X(self, x):
        return self.x0 + (x - self.xr[0]) / (self.xr[1] - self.xr[0]) * self.w

    def Y(self, y):
        return self.y0 + self.h - (y - self.yr[0]) / (self.yr[1] - self.yr[0]) * self.h

    def inside(self, y):
        return self.yr[0] <= y <= self.yr[1]


def polyline(panel, xs, f, colour, dash="", width=1.6):
    segs, cur = [], []
    for x in xs:
        y = f(x)
        if y == y and panel.inside(y):
            cur.append("%.1f,%.1f" % (panel.X(x), panel.Y(y)))
        elif cur:
            segs.append(cur)
            cur = []
    if cur:
        segs.append(cur)
    da = ' stroke-dasharray="%s"' % dash if dash else ""
    return "".join('<polyline fill="none" stroke="%s" stroke-width="%.1f"%s points="%s"/>\n'
                   % (colour, width, da, " ".join(s)) for s in segs)


def axes(panel, xticks, yticks, xlabel, ylabel, yfmt):
    o = ['<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="#000"/>\n'
         % (panel.x0, panel.y0, panel.w, panel.h)]
    for t in xticks:
        x = panel.X(t)
        o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>\n' % (x, panel.y0, x, panel.y0 + panel.h))
        o.append('<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>\n' % (x, panel.y0 + panel.h + 16, t))
    for t in yticks:
        y = panel.Y(t)
        o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>\n' % (panel.x0, y, panel.x0 + panel.w, y))
        o.append('<text x="%.1f" y="%.1f" text-anchor="end">%s</text>\n' % (panel.x0 - 6, y + 4, yfmt % t))
    if xlabel:
        o.append('<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>\n'
                 % (panel.x0 + panel.w / 2, panel.y0 + panel.h + 34, xlabel))
    o.append('<text transform="translate(%.1f,%.1f) rotate(-90)" text-anchor="middle">%s</text>\n'
             % (panel.x0 - 48, panel.y0 + panel.h / 2, ylabel))
    return "".join(o)


MARKERS = {0: ("#1f77b4", "circle"), 1: ("#d62728", "square"), 2: ("#2ca02c", "diamond"), 3: ("#9467bd", "circle")}


def marker(x, y, colour, shape, r=3.6):
    if shape == "square":
        return '<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"/>\n' % (x - r, y - r, 2 * r, 2 * r, colour)
    if shape == "diamond":
        return '<polygon points="%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f" fill="%s"/>\n' % (
            x, y - r * 1.3, x + r * 1.3, y, x, y + r * 1.3, x - r * 1.3, y, colour)
    return '<circle cx="%.1f" cy="%.1f" r="%.1f" fill="%s"/>\n' % (x, y, r, colour)


def errbar(panel, x, ylo, yhi, colour):
    lo, hi = max(ylo, panel.yr[0]), min(yhi, panel.yr[1])
    if hi <= lo:
        return ""
    X = panel.X(x)
    return ('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-width="1.2"/>\n'
            % (X, panel.Y(lo), X, panel.Y(hi), colour))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, pts = sys.argv[1], read_runs(sys.argv[2:])
    sizes = sorted({p[0] for p in pts})
    W, H = 1000, 780
    top = Panel(80, 40, 500, 390, (0.0, 0.75), (0.0, 14.0))
    zoom = Panel(660, 40, 310, 390, (0.62, 0.725), (7.0, 11.5))
    bot = Panel(80, 500, 890, 210, (0.0, 0.75), (-0.6, 1.0))
    xs = [i / 1500.0 * 0.75 for i in range(1, 1501)]
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">\n'
         % (W, H), '<rect width="100%" height="100%" fill="#fff"/>\n']
    o.append('<text x="%d" y="22" text-anchor="middle" font-size="14">Hard disks in a periodic box: '
             'Z = PA/(NkT) from the collision virial (EXACT world); right: the dense end</text>\n' % (W // 2))
    xt = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]
    o.append(axes(top, xt, [0, 2, 4, 6, 8, 10, 12, 14], "area fraction eta", "Z", "%g"))
    o.append(axes(zoom, [0.63, 0.65, 0.67, 0.69, 0.71], [7, 8, 9, 10, 11], "area fraction eta", "Z", "%g"))
    o.append(axes(bot, xt, [-0.6, -0.4, -0.2, 0, 0.2, 0.4, 0.6, 0.8, 1.0], "area fraction eta",
                  "Z / Z_KR - 1  (%)", "%g"))
    # the coexistence region
    for p in (top, zoom, bot):
        o.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="#f5a623" fill-opacity="0.15"/>\n'
                 % (p.X(0.700), p.y0, p.X(0.716) - p.X(0.700), p.h))
    # curves
    for p in (top, zoom):
        zx = [x for x in xs if p.xr[0] <= x <= p.xr[1]]
        o.append(polyline(p, zx, z_h, "#888", "6,4"))
        o.append(polyline(p, [x for x in zx if x <= ETA_KR_MAX], z_kr, "#000"))
        o.append(polyline(p, [0.700 + i * 0.016 / 50 for i in range(51)], z_engel, "#f5a623", "", 3.0))
    o.append(polyline(bot, [x for x in xs if x <= ETA_KR_MAX], lambda e: 100.0 * (z_h(e) / z_kr(e) - 1.0), "#888", "6,4"))
    o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#000" stroke-width="1.2"/>\n'
             % (bot.x0, bot.Y(0), bot.X(ETA_KR_MAX), bot.Y(0)))
    # points
    for k, n in enumerate(sizes):
        colour, shape = MARKERS[k % len(MARKERS)]
        for (m, eta, z, err) in pts:
            if m != n:
                continue
            for p in (top, zoom):
                if p.xr[0] <= eta <= p.xr[1] and p.inside(z):
                    o.append(errbar(p, eta, z - err, z + err, colour))
                    o.append(marker(p.X(eta), p.Y(z), colour, shape))
            if eta <= ETA_KR_MAX:
                zk = z_kr(eta)
                dev, de = 100.0 * (z / zk - 1.0), 100.0 * err / zk
                o.append(errbar(bot, eta, dev - de, dev + de, colour))
                if bot.inside(dev):
                    o.append(marker(bot.X(eta), bot.Y(dev), colour, shape, 3.0))
    # legend
    lx, ly = top.x0 + 16, top.y0 + 18
    items = [("line", "#000", "", "Kolafa and Rottner 2006 fit (to eta 0.707)"),
             ("line", "#888", "6,4", "Henderson 1975"),
             ("line", "#f5a623", "", "Engel et al. 2013: coexistence, beta P sigma^2 = 9.185")]
    for k, n in enumerate(sizes):
        colour, shape = MARKERS[k % len(MARKERS)]
        items.append(("mark", colour, shape, "measured, N = %d (error bars: block averages)" % n))
    for i, (kind, colour, style, text) in enumerate(items):
        y = ly + 18 * i
        if kind == "line":
            da = ' stroke-dasharray="%s"' % style if style else ""
            o.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-width="2"%s/>\n'
                     % (lx, y - 4, lx + 28, y - 4, colour, da))
        else:
            o.append(marker(lx + 14, y - 4, colour, style))
        o.append('<text x="%.1f" y="%.1f">%s</text>\n' % (lx + 36, y, text))
    o.append('<text x="%.1f" y="%.1f" fill="#b07000" text-anchor="end">liquid-hexatic coexistence</text>\n'
             % (zoom.X(0.699), zoom.Y(7.3)))
    o.append('<text x="%.1f" y="%.1f" fill="#555">Henderson</text>\n' % (bot.X(0.50), bot.Y(0.75)))
    o.append("</svg>\n")
    with open(out, "w") as f:
        f.write("".join(o))


if __name__ == "__main__":
    main()
