% One oscillator x'' + 2 zeta omega_n x' + omega_n^2 x = F cos(omega t), eq. (1), by
% the fixed-step methods written out (a learner's Newmark, Verlet, RK4 loops).
c = 2*zeta*omega_n; k = omega_n^2;
acc = @(t, x, v) F*cos(omega*t) - c*v - k*x;
N = ceil(t_end/h*(1 - 1e-12)); hs = t_end/N;   % N equal steps of hs <= h
out.omega_n = omega_n;
out.h_taken = hs;
out.omega_n_h = omega_n*hs;
out.h_stable_explicit = 2/omega_n;
% the exact motion: steady state plus the free motion that meets x0, v0
Dz = k - omega^2 + 1i*c*omega; Ap = F/Dz;
xp = @(t) real(Ap*exp(1i*omega*t)); vp = @(t) real(1i*omega*Ap*exp(1i*omega*t));
s12 = roots([1 c k]);
if abs(s12(1) - s12(2)) > 1e-9*omega_n
  C = [1 1; s12(1) s12(2)] \ [x0 - xp(0); v0 - vp(0)];
  x = @(t) real(C(1)*exp(s12(1)*t) + C(2)*exp(s12(2)*t)) + xp(t);
else
  sr = real(s12(1)); Ah = x0 - xp(0); Bh = v0 - vp(0) - sr*Ah;
  x = @(t) (Ah + Bh*t).*exp(sr*t) + xp(t);
end
out.amplitude = max(abs(x(linspace(0, t_end, 501))));
% the work-precision sweeps run over at most 20 periods of the fastest motion
wmax = omega_n; if F ~= 0, wmax = max(omega_n, omega); end
out.t_sweep = min(t_end, 20*2*pi/wmax);
% the long free run: x'' + omega_n^2 x = 0 from x = 1, 20 steps a period. Each
% method's step is linear in (x, v): written out once, it is a 2 x 2 matrix M,
% and every stride steps (where the energy is looked at, as on the plot) M^stride.
hE = 2*pi/omega_n/20; NE = 20*periods; stride = ceil(NE/500);
aa = @(s) [s(1) + hE*s(2) - hE^2/4*k*s(1) + hE^2/4*(-k*(s(1) + hE*s(2) - hE^2/4*k*s(1))/(1 + k*hE^2/4)); ...
           s(2) + hE/2*(-k*s(1) - k*(s(1) + hE*s(2) - hE^2/4*k*s(1))/(1 + k*hE^2/4))];   % average acceleration
vv = @(s) [s(1) + hE*(s(2) - hE/2*k*s(1)); ...
           s(2) - hE/2*k*s(1) - hE/2*k*(s(1) + hE*(s(2) - hE/2*k*s(1)))];                % Stormer-Verlet
f = @(y) [y(2); -k*y(1)];
rk = @(y) y + hE/6*(f(y) + 2*f(y + hE/2*f(y)) + 2*f(y + hE/2*f(y + hE/2*f(y))) ...
           + f(y + hE*f(y + hE/2*f(y + hE/2*f(y)))));                                  % classical Runge-Kutta
E = @(s) (0.5*s(2)^2 + 0.5*k*s(1)^2)/(0.5*k) - 1;      % relative energy error from x = 1
steps = {aa, vv, rk}; worst = [0 0 0]; last = [0 0 0];
for j = 1:3
  M = [steps{j}([1; 0]), steps{j}([0; 1])];
  Ms = M^stride; s = [1; 0];
  for n = stride:stride:NE
    s = Ms*s; worst(j) = max(worst(j), abs(E(s)));
  end
  s = M^mod(NE, stride)*s; worst(j) = max(worst(j), abs(E(s))); last(j) = E(s);
end
out.energy_error_newmark = worst(1);
out.energy_error_verlet = worst(2);
out.energy_drift_rk4 = last(3);                  % eq. (7): |R(i omega h)|^(2N) - 1
