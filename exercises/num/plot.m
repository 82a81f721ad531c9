% num-plot: sample f on [a, b] (eq. 1), refine its extremes between the
% samples by golden section (eq. 6), and the area by composite 5-point
% Gauss-Legendre (eq. 5) and by the trapezoids of the plot (eq. 3).
x = linspace(a, b, points);
y = f(x);
ok = isfinite(y);
out.points = sum(ok);
% the samples can miss a narrow peak: search a grid at least ten times finer
xf = linspace(a, b, max(10 * (points - 1) + 1, 20001));
yf = f(xf);
keep = isfinite(yf);
xo = xf(keep);
yo = yf(keep);
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
    % panels of width 0.1 at most (narrow beside a wave of period 1), on a
    % grid anchored at x = 0, so that the panels near 0 are placed exactly
    h0 = min(0.1, (b - a) / 512);
    e = unique([a, h0 * (ceil(a / h0):floor(b / h0)), b]);
    mid = (e(1:end-1) + e(2:end)) / 2;
    h = (e(2:end) - e(1:end-1)) / 2;
    q = h .* (wt * f(mid + t * h));          % one number per panel
    s = 0;                                   % Kahan's compensated sum over the panels:
    c = 0;                                   % the partial sums can be far larger than the total
    for k = 1:numel(q)
        yk = q(k) - c;
        tk = s + yk;
        c = (tk - s) - yk;
        s = tk;
    end
    out.integral = s;
    out.integral_plot = (x(2) - x(1)) * (sum(y) - (y(1) + y(end)) / 2);
end
