% Reactions from sum Fy = 0 and sum M = 0, eqs. (2)-(3).
two = ~strcmp(supports, 'cantilever');
o = 0;
if two, o = a; end                        % moments about the pin (or the clamp)
F = 0; Mo = 0;
for i = 1:size(point_loads, 1)
  F = F + point_loads(i, 2);  Mo = Mo + point_loads(i, 2) * (point_loads(i, 1) - o);
end
for i = 1:size(distributed, 1)
  d = distributed(i, :);  l = d(2) - d(1);  W = (d(3) + d(4)) * l / 2;
  F = F + W;  Mo = Mo + (d(1) - o) * W + l^2 * (d(3) / 6 + d(4) / 3);
end
for i = 1:size(moments, 1)
  Mo = Mo + moments(i, 2);
end
if two
  rx = [a b];  ry = [-F + Mo / (b - a), -Mo / (b - a)];  rc = [0 0];
else
  rx = 0;  ry = -F;  rc = -Mo;
end
forces = [point_loads; rx' ry'];  couples = [moments; rx' rc'];
xs = [0 L rx forces(:, 1)' couples(:, 1)'];
if ~isempty(distributed), xs = [xs distributed(:, 1)' distributed(:, 2)']; end
xs = unique(xs);
% Sweep the segments: q linear, V quadratic, M cubic in s = x - xs(k), eqs. (4)-(5).
V = 0; M = 0; T = 0; Y = 0; seg = zeros(numel(xs) - 1, 6);
best = [0 0 0 0];                         % [V_extreme x_V M_extreme x_M]
for k = 1:numel(xs) - 1
  x0 = xs(k);  h = xs(k + 1) - x0;
  V = V + sum(forces(forces(:, 1) == x0, 2));   % a point force makes V jump
  M = M - sum(couples(couples(:, 1) == x0, 2)); % a couple makes M jump by -C
  q0 = 0; q1 = 0;
  for i = 1:size(distributed, 1)
    d = distributed(i, :);
    if d(1) <= x0 && x0 < d(2)
      sl = (d(4) - d(3)) / (d(2) - d(1));  q0 = q0 + d(3) + sl * (x0 - d(1));  q1 = q1 + sl;
    end
  end
  sv = [0 h];
  if q1 ~= 0, sv = [sv, -q0 / q1]; end     % V stationary where q = 0
  sm = [0 h];
  if q1 ~= 0, sm = [sm, roots([q1 / 2, q0, V])']; elseif q0 ~= 0, sm = [sm, -V / q0]; end
  sv = sort(real(sv(imag(sv) == 0 & real(sv) >= 0 & real(sv) <= h)));
  sm = sort(real(sm(imag(sm) == 0 & real(sm) >= 0 & real(sm) <= h)));
  for s = sv
    v = V + q0 * s + q1 * s^2 / 2;
    if abs(v) > abs(best(1)) * (1 + 1e-12), best(1:2) = [v, x0 + s]; end
  end
  for s = sm
    m = M + V * s + q0 * s^2 / 2 + q1 * s^3 / 6;
    if abs(m) > abs(best(3)) * (1 + 1e-12), best(3:4) = [m, x0 + s]; end
  end
  seg(k, :) = [x0, q0, q1, V, M, 0];
  V = V + q0 * h + q1 * h^2 / 2;
  M = M + (seg(k, 4) * h + q0 * h^2 / 2 + q1 * h^3 / 6);
end
out.V_extreme = best(1);  out.x_V_extreme = best(2);
out.M_extreme = best(3);  out.x_M_extreme = best(4);
fprintf('reactions: x = %s m, Ry = %s N, C = %s N m\n', mat2str(rx), mat2str(ry), mat2str(rc));
if EI > 0                                 % EI y'' = M, integrated twice, eq. (7)
  yk = zeros(1, numel(xs));  tk = zeros(1, numel(xs));
  for k = 1:numel(xs) - 1
    h = xs(k + 1) - xs(k);  c = seg(k, :);
    tk(k + 1) = tk(k) + (c(5) * h + c(4) * h^2 / 2 + c(2) * h^3 / 6 + c(3) * h^4 / 24) / EI;
    yk(k + 1) = yk(k) + tk(k) * h + (c(5) * h^2 / 2 + c(4) * h^3 / 6 + c(2) * h^4 / 24 + c(3) * h^5 / 120) / EI;
  end
  th0 = 0; y0 = 0;                        % cantilever: y = y' = 0 at x = 0
  if two
    ya = yk(xs == a);  yb = yk(xs == b);  th0 = (ya - yb) / (b - a);  y0 = -ya - th0 * a;
  end
  out.y_max = 0;  out.x_y_max = 0;
  for k = 1:numel(xs) - 1
    c = seg(k, :);  h = xs(k + 1) - xs(k);
    th = @(s) tk(k) + th0 + (c(5) * s + c(4) * s.^2 / 2 + c(2) * s.^3 / 6 + c(3) * s.^4 / 24) / EI;
    yy = @(s) yk(k) + y0 + th0 * xs(k) + (tk(k) + th0) * s + (c(5) * s.^2 / 2 + c(4) * s.^3 / 6 + c(2) * s.^4 / 24 + c(3) * s.^5 / 120) / EI;
    ss = linspace(0, h, 65);  cand = [0 h];
    for j = 1:64
      if th(ss(j)) * th(ss(j + 1)) < 0, cand = [cand, fzero(th, [ss(j) ss(j + 1)])]; end
    end
    for s = sort(cand)
      if abs(yy(s)) > abs(out.y_max) * (1 + 1e-12), out.y_max = yy(s);  out.x_y_max = xs(k) + s; end
    end
  end
end
