% Dynamics of a two-link arm: torques of a planned move, then a forward simulation.
if abs(q2_0) >= pi || abs(q2_1) >= pi
  error('q2 = +-pi folds link 2 onto link 1: out of reach');
end
% the time law s(tau) and its derivatives, eqs. (2)-(3)
if strcmp(trajectory, 'quintic')
  s = @(u) 10*u.^3 - 15*u.^4 + 6*u.^5;  ds = @(u) 30*u.^2.*(1-u).^2;  dds = @(u) 60*u.*(1-u).*(1-2*u);
else
  s = @(u) 3*u.^2 - 2*u.^3;  ds = @(u) 6*u.*(1-u);  dds = @(u) 6 - 12*u;
end
d1 = q1_1 - q1_0;  d2 = q2_1 - q2_0;
% inverse dynamics, eq. (1): tau = M q'' + c + G at time t
tau = @(t) [ ...
  (m1*l1^2/3 + m2*(l1^2 + l2^2/3 + l1*l2*cos(q2_0 + d2*s(t/T)))) .* d1.*dds(t/T)/T^2 ...
  + m2*(l2^2/3 + l1*l2*cos(q2_0 + d2*s(t/T))/2) .* d2.*dds(t/T)/T^2 ...
  - m2*l1*l2*sin(q2_0 + d2*s(t/T)) .* (d1*ds(t/T)/T .* d2.*ds(t/T)/T + (d2*ds(t/T)/T).^2/2) ...
  + (m1/2 + m2)*g*l1*cos(q1_0 + d1*s(t/T)) + m2*g*l2/2*cos(q1_0 + d1*s(t/T) + q2_0 + d2*s(t/T)); ...
  m2*(l2^2/3 + l1*l2*cos(q2_0 + d2*s(t/T))/2) .* d1.*dds(t/T)/T^2 + m2*l2^2/3 * d2.*dds(t/T)/T^2 ...
  + m2*l1*l2*sin(q2_0 + d2*s(t/T)) .* (d1*ds(t/T)/T).^2/2 ...
  + m2*g*l2/2*cos(q1_0 + d1*s(t/T) + q2_0 + d2*s(t/T))];
% the largest |tau_j|: the best of 2001 samples, refined by golden sections
tt = linspace(0, T, 2001);
tq = tau(tt);
for j = 1:2
  f = @(t) abs([j == 1, j == 2] * tau(t));
  [~, i] = max(abs(tq(j, :)));
  a = tt(max(i - 1, 1));  b = tt(min(i + 1, numel(tt)));  r = (sqrt(5) - 1) / 2;
  for it = 1:80
    x1 = b - r * (b - a);  x2 = a + r * (b - a);
    if f(x1) > f(x2)
      b = x2;
    else
      a = x1;
    end
  end
  tm = (a + b) / 2;
  if abs(tq(j, i)) >= f(tm)
    tm = tt(i);                          % an end point, or a kink of |tau|
  end
  if j == 1
    out.tau1_max = f(tm);  out.t_tau1_max = tm;
  else
    out.tau2_max = f(tm);  out.t_tau2_max = tm;
  end
end
% the reach and the singular configurations, eq. (4)
if q2_0 * q2_1 <= 0
  out.det_J_min = 0;  cmax = 1;
else
  out.det_J_min = l1*l2*min(abs(sin([q2_0 q2_1])));  cmax = max(cos([q2_0 q2_1]));
end
out.reach_max = sqrt(l1^2 + l2^2 + 2*l1*l2*cmax);
% the work of the motors against the rise of the potential energy, eq. (6)
V = @(a, b) g*((m1/2 + m2)*l1*sin(a) + m2*l2/2*sin(a + b));
out.delta_V = V(q1_1, q2_1) - V(q1_0, q2_0);
% by 5-point Gauss-Legendre quadrature on 64 panels
gx = [-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640];
gw = [0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891];
edges = linspace(0, T, 65);
tg = reshape((edges(1:64) + edges(2:65))' / 2 + (T / 128) * gx, 1, []);
wg = reshape(repmat((T / 128) * gw, 64, 1), 1, []);
tqg = tau(tg);
out.work = sum(wg .* (tqg(1, :) .* d1 .* ds(tg / T) / T + tqg(2, :) .* d2 .* ds(tg / T) / T));
% when the arm passes the stretched configuration q2 = 0
if q2_0 == 0
  out.t_singular = 0;
elseif q2_1 == 0
  out.t_singular = T;
elseif q2_0 * q2_1 < 0
  out.t_singular = fzero(@(t) q2_0 + d2 * s(t / T), [0 T]);
end
% forward dynamics, eq. (5), driven by the same torques
M = @(q) [m1*l1^2/3 + m2*(l1^2 + l2^2/3 + l1*l2*cos(q(2))), m2*(l2^2/3 + l1*l2*cos(q(2))/2); ...
          m2*(l2^2/3 + l1*l2*cos(q(2))/2), m2*l2^2/3];
h = @(q, w) [-m2*l1*l2*sin(q(2))*(w(1)*w(2) + w(2)^2/2) + (m1/2 + m2)*g*l1*cos(q(1)) + m2*g*l2/2*cos(q(1)+q(2)); ...
             m2*l1*l2*sin(q(2))*w(1)^2/2 + m2*g*l2/2*cos(q(1)+q(2))];
f = @(t, y) [y(3:4); M(y(1:2)) \ (tau(t) - h(y(1:2), y(3:4)))];
opts = odeset('RelTol', 1e-10, 'AbsTol', 1e-12);
[ts, y] = ode45(f, linspace(0, T, points), [q1_0; q2_0; 0; 0], opts);
fprintf('forward simulation by ode45: largest |q - q_planned| = %.3g rad\n', ...
        max(max(abs(y(:, 1:2) - [q1_0 + d1*s(ts/T), q2_0 + d2*s(ts/T)]))));
