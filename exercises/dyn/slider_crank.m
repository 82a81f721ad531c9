% Slider-crank coasting through its dead centres, in the crank angle alone.
if l <= 1.05 * r
  error('the rod must be longer than the crank');
end
lam = r / l;
C = @(p) sqrt(1 - (lam * sin(p)).^2);                 % cos of the rod angle
u = @(p) lam * cos(p) ./ C(p);                        % -(rod angle rate) per unit crank speed
% the effective inertia J(phi), eq. (5), from the velocities per unit crank speed
J = @(p) J_crank + m_rod * ((r * sin(p) .* (1 + u(p)/2)).^2 + (r * cos(p) / 2).^2) ...
    + J_rod * u(p).^2 + m_piston * (r * sin(p) .* (1 + u(p))).^2;
out.J_dead_centre = J(0);
% its extremes over half a turn: the best of 361 samples, refined by golden sections
pp = linspace(0, pi, 361);
for sgn = [-1 1]
  [~, i] = max(sgn * J(pp));
  a = pp(max(i - 1, 1));  b = pp(min(i + 1, 361));  g = (sqrt(5) - 1) / 2;
  for it = 1:60
    x1 = b - g * (b - a);  x2 = a + g * (b - a);
    if sgn * J(x1) > sgn * J(x2)
      b = x2;
    else
      a = x1;
    end
  end
  v = sgn * max(sgn * [J(pp(i)), J(x1), J(x2)]);
  if sgn < 0
    out.J_min = v;
  else
    out.J_max = v;
  end
end
% the reduced equation J phi'' + J'(phi) phi'^2 / 2 = torque (dJ by a 4th-order central
% difference), integrated far more tightly than the server's rtol
dJ = @(p) (8 * (J(p + 1e-3) - J(p - 1e-3)) - (J(p + 2e-3) - J(p - 2e-3))) / 12e-3;
f = @(t, y) [y(2); (torque - dJ(y(1)) * y(2)^2 / 2) / J(y(1))];
[t, y] = ode45(f, linspace(0, t_end, points), [0; omega0], odeset('RelTol', 1e-12, 'AbsTol', 1e-12));
out.omega_min = min(y(:, 2));
out.omega_max = max(y(:, 2));
out.omega_end = y(end, 2);
if out.omega_min > 0 || out.omega_max < 0
  wmean = (sum(y(:, 2)) - (y(1, 2) + y(end, 2)) / 2) / (numel(t) - 1);
  out.fluctuation = (out.omega_max - out.omega_min) / abs(wmean);
end
out.revolutions = y(end, 1) / (2 * pi);
% the joint forces: M q'' + Phi_q' lambda = Q with Phi_q q'' = gamma, at every point, by A\b
Mq = diag([J_crank, m_rod, m_rod, J_rod, m_piston]);
FA = zeros(numel(t), 1);  FB = FA;  N = FA;
for i = 1:numel(t)
  p1 = y(i, 1);  w = y(i, 2);  s2 = -lam * sin(p1);  c2 = C(p1);  w2 = -r * cos(p1) * w / (l * c2);
  Pq = [r*sin(p1), 1, 0, l/2*s2, 0; -r*cos(p1), 0, 1, -l/2*c2, 0; 0, 1, 0, -l/2*s2, -1; 0, 0, 1, l/2*c2, 0];
  gam = [-(r*cos(p1)*w^2 + l/2*c2*w2^2); -(r*sin(p1)*w^2 + l/2*s2*w2^2); l/2*c2*w2^2; l/2*s2*w2^2];
  x = [Mq, Pq'; Pq, zeros(4)] \ [torque; 0; 0; 0; 0; gam];
  FA(i) = hypot(x(6), x(7));  FB(i) = hypot(x(8), x(9));  N(i) = -x(9);
end
out.F_A_max = max(FA);
out.F_B_max = max(FB);
out.N_max = max(abs(N));
% the energy balance, eq. (6)
fprintf('energy balance, worst: %.3g J\n', max(abs(J(y(:,1)) .* y(:,2).^2 / 2 - J(0) * omega0^2 / 2 - torque * y(:,1))));
