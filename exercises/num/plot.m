% num-plot: sample f on [a, b] (eq. 1), refine its extremes between the
% samples by golden section (eq. 6), and the area by composite 5-point
% Gauss-Legendre (eq. 5) and by the trapezoids of the plot (eq. 3).
x = linspace(a, b, points);
y = f(x);
ok = isfinite(y);
out.points = sum(ok);
xo = x(ok);
yo = y(ok);
g = (sqrt(5) - 1) / 2;
names = {'max', 'min'};
for w = 1:2
    s = 3 - 2 * w;                           % +1: largest, -1: smallest
    [~, k] = max(s * yo);
    lo = xo(max(k - 1, 1));
    hi = xo(min(k + 1, numel(xo)));
    c = hi - g * (hi - lo);
    d = lo + g * (hi - lo);
    for it = 1:80                            % keep the part that holds the extreme
        if s * f(c) >= s * f(d)
            hi = d; d = c; c = hi - g * (hi - lo);
        else
            lo = c; c = d; d = lo + g * (hi - lo);
        end
    end
    xm = (lo + hi) / 2;
    out.(names{w}) = f(xm);
    out.(['x_' names{w}]) = xm;
end
if all(ok)
    t = [-0.906179845938664; -0.5384693101056831; 0; 0.5384693101056831; 0.906179845938664];
    wt = [0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891];
    m = 512;                                 % panels
    e = linspace(a, b, m + 1);
    h = (b - a) / m / 2;
    mid = (e(1:end-1) + e(2:end)) / 2;
    out.integral = h * sum(wt * f(mid + h * t));
    out.integral_plot = (x(2) - x(1)) * (sum(y) - (y(1) + y(end)) / 2);
end
