% The model, eq. (1):  m x'' + c x' + k x = F0 cos(omega t)
omega_n = sqrt(k / m);                 % natural frequency [rad/s]
zeta = c / (2 * sqrt(k * m));          % damping ratio
r = omega / omega_n;                   % frequency ratio

% The steady state X cos(omega t - phase), eqs. (3)-(4): the complex
% dynamic stiffness k - m omega^2 + i c omega divides the force.
Z = k - m * omega^2 + 1i * c * omega;
X = F0 / abs(Z);
phase = angle(Z);                      % the lag, in [0, pi]
magnification = X / (F0 / k);

if zeta < 1 - 1e-12
    regime = 0;                        % underdamped
elseif zeta <= 1 + 1e-12
    regime = 1;                        % critically damped
else
    regime = 2;                        % overdamped
end

% The whole response by ode45, to compare with the closed form on the page
[t, y] = ode45(@(t, y) [y(2); (F0 * cos(omega * t) - c * y(2) - k * y(1)) / m], ...
               [0 t_end], [x0; v0], odeset('RelTol', 1e-8, 'AbsTol', 1e-12));
x_end = y(end, 1);                     % x(t_end), by the integrator

out.omega_n = omega_n;
out.zeta = zeta;
out.X = X;
out.phase = phase;
out.magnification = magnification;
out.r = r;
out.regime = regime;
