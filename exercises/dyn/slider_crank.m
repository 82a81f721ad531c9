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
pp = linspace(0, pi, 20001);
out.J_min = min(J(pp));
out.J_max = max(J(pp));
% the reduced equation J phi'' + J'(phi) phi'^2 / 2 = torque (dJ by a central difference)
dJ = @(p) (J(p + 1e-6) - J(p - 1e-6)) / 2e-6;
f = @(t, y) [y(2); (torque - dJ(y(1)) * y(2)^2 / 2) / J(y(1))];
opts = odeset('RelTol', rtol, 'AbsTol', rtol);
[t, y] = ode45(f, linspace(0, t_end, points), [0; omega0], opts);
out.omega_min = min(y(:, 2));
out.omega_max = max(y(:, 2));
out.omega_end = y(end, 2);
if out.omega_min > 0 || out.omega_max < 0
  out.fluctuation = (out.omega_max - out.omega_min) / abs(trapz(t, y(:, 2)) / t_end);
end
out.revolutions = y(end, 1) / (2 * pi);
% the energy balance, eq. (6)
fprintf('energy balance, worst: %.3g J\n', max(abs(J(y(:,1)) .* y(:,2).^2 / 2 - J(0) * omega0^2 / 2 - torque * y(:,1))));
