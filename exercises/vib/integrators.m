% One oscillator x'' + 2 zeta omega_n x' + omega_n^2 x = F cos(omega t), eq. (1), by
% the fixed-step methods written out (a learner's Newmark, Verlet, RK4 loops).
c = 2*zeta*omega_n; k = omega_n^2;
acc = @(t, x, v) F*cos(omega*t) - c*v - k*x;
N = ceil(t_end/h*(1 - 1e-12)); hs = t_end/N;   % N equal steps of hs <= h
out.omega_n = omega_n;
out.h_taken = hs;
out.omega_n_h = omega_n*hs;
out.h_stable_explicit = 2/omega_n;
% the exact motion (ode45 to 1e-12 stands in for mechmat's closed form here)
t = linspace(0, t_end, 501);
[~, y] = ode45(@(t, y) [y(2); acc(t, y(1), y(2))], t, [x0; v0], odeset('RelTol', 1e-12, 'AbsTol', 1e-14));
out.amplitude = max(abs(y(:, 1)));
% the long free run: x'' + omega_n^2 x = 0 from x = 1, 20 steps a period
hE = 2*pi/omega_n/20; NE = 20*periods; E = @(x, v) 0.5*v^2 + 0.5*k*x^2; E0 = E(1, 0);
x = 1; v = 0; a = -k*x; worst_aa = 0;          % average acceleration, eq. (3) with beta 1/4, gamma 1/2
for n = 1:NE
  a1 = -k*(x + hE*v + hE^2/4*a)/(1 + k*hE^2/4);
  x = x + hE*v + hE^2/4*(a + a1); v = v + hE/2*(a + a1); a = a1;
  worst_aa = max(worst_aa, abs(E(x, v)/E0 - 1));
end
x = 1; v = 0; worst_v = 0;                     % Stormer-Verlet, eq. (4)
for n = 1:NE
  vh = v - hE/2*k*x; x = x + hE*vh; v = vh - hE/2*k*x;
  worst_v = max(worst_v, abs(E(x, v)/E0 - 1));
end
y = [1; 0]; f = @(y) [y(2); -k*y(1)];           % classical Runge-Kutta
for n = 1:NE
  k1 = f(y); k2 = f(y + hE/2*k1); k3 = f(y + hE/2*k2); k4 = f(y + hE*k3);
  y = y + hE/6*(k1 + 2*k2 + 2*k3 + k4);
end
out.energy_error_newmark = worst_aa;
out.energy_error_verlet = worst_v;
out.energy_drift_rk4 = E(y(1), y(2))/E0 - 1;   % eq. (7): |R(i omega h)|^(2N) - 1
