% Tangential and normal coordinates along the path x(t), y(t): speed,
% a_t, a_n, curvature and the centre of curvature (1)-(2).
r = @(s) [x(s); y(s)];
% v and a by Ridders' extrapolation of central differences: differences at
% h0, h0/1.4, ..., extrapolated to h = 0 in a Neville table
h0 = 0.05 * min(t1 - t0, 1);
f0 = r(t);  Dv = zeros(2, 10);  Da = zeros(2, 10);  hh = h0;
for i = 1:10
  tp = t + hh;  tm = t - hh;  hs = (tp - tm) / 2;
  fp = r(tp);  fm = r(tm);
  Dv(:, i) = (fp - fm) / (2*hs);
  Da(:, i) = (fp - 2*f0 + fm) / hs^2;
  hh = hh / 1.4;
end
d = zeros(2, 2);
for o = 1:2
  for c = 1:2
    if o == 1, Dr = Dv(c, :); else, Dr = Da(c, :); end
    tab = zeros(10);  tab(1, 1) = Dr(1);  err = Inf;  best = Dr(1);
    for i = 2:10
      tab(1, i) = Dr(i);  fac = 1.96;
      for j = 2:i
        tab(j, i) = (tab(j - 1, i)*fac - tab(j - 1, i - 1)) / (fac - 1);
        fac = fac * 1.96;
        ej = max(abs(tab(j, i) - tab(j - 1, i)), abs(tab(j, i) - tab(j - 1, i - 1)));
        if ej <= err, err = ej; best = tab(j, i); end
      end
      if i >= 5 && abs(tab(i, i) - tab(i - 1, i - 1)) >= 2*err
        break
      end
    end
    d(c, o) = best;
  end
end
v = d(:, 1);  a = d(:, 2);
out.v = norm(v);
out.a = norm(a);
T = v / out.v;                             % unit tangent
N = [-T(2); T(1)];                         % unit normal, to the left
cr = v(1)*a(2) - v(2)*a(1);                % v x a
out.a_t = dot(v, a) / out.v;               % (2)
out.a_n = abs(cr) / out.v;
out.kappa = cr / out.v^3;
out.direction = atan2(T(2), T(1));
if out.kappa ~= 0
  out.rho = 1 / abs(out.kappa);
  C = r(t) + N / out.kappa;                % centre of curvature
  out.centre_x = C(1);  out.centre_y = C(2);
end
% check: a_t is the rate of change of the speed (a plain central difference
% of |dr/dt|, itself by central differences: about 7 digits)
sp = @(s) norm((r(s + 1e-4) - r(s - 1e-4)) / 2e-4);
fprintf('check: a_t %.10g, d|v|/dt by differences %.10g\n', out.a_t, (sp(t + 1e-3) - sp(t - 1e-3)) / 2e-3);
