% num-nonlinear-roots: every root of f on [a, b]: cut [a, b] into n parts,
% keep each part where f changes sign (eq. 2), refine it by fzero.
xs = a + (b - a) * (0:n) / n;
fs = f(xs);
x = [];
for i = 1:n
    if fs(i) == 0                            % a root on the grid, counted once
        x(end + 1) = xs(i);
    elseif fs(i) * fs(i + 1) < 0
        r = fzero(f, [xs(i), xs(i + 1)], optimset('TolX', tol / 8));   % well within tol
        if abs(f(r)) <= max(abs(fs(i)), abs(fs(i + 1)))   % |f| grew: a pole, not a root
            x(end + 1) = r;
        end
    end
end
if fs(end) == 0
    x(end + 1) = xs(end);
end
out.count = numel(x);
if ~isempty(x)
    out.x1 = x(1);
end
