% A mass on a spring and damper over a support moving as y = Y cos(omega t):
% m x'' + c x' + k x = k Y cos(omega t) - c Y omega sin(omega t), eq. (2).
omega_n = sqrt(k/m);
zeta = c/(2*sqrt(k*m));
r = omega/omega_n;
D = k - m*omega^2 + 1i*c*omega;           % dynamic stiffness
T = abs(k + 1i*c*omega)/abs(D);           % transmissibility, eq. (3)
out.omega_n = omega_n;
out.zeta = zeta;
out.r = r;
out.transmissibility = T;
out.X = T*Y;
% the lag of x behind y as one angle, eq. (4): arg(D (k - i c omega))
out.phase = atan2(c*m*omega^3, k*real(D) + (c*omega)^2);
out.Z = Y*m*omega^2/abs(D);               % stretch of the spring
out.force_transmitted = m*omega^2*T*Y;    % eq. (5)
out.isolates = T < 1;
% the response from x0, v0: steady state plus the free motion
A = Y*(k + 1i*c*omega)/D;                 % x_p = Re(A e^(i omega t))
xp = @(t) real(A*exp(1i*omega*t));
vp = @(t) real(1i*omega*A*exp(1i*omega*t));
s12 = roots([m c k]);
if abs(s12(1) - s12(2)) > 1e-9*omega_n
  C = [1 1; s12(1) s12(2)] \ [x0 - xp(0); v0 - vp(0)];
  x = @(t) real(C(1)*exp(s12(1)*t) + C(2)*exp(s12(2)*t)) + xp(t);
else
  s = real(s12(1)); Ah = x0 - xp(0); Bh = v0 - vp(0) - s*Ah;
  x = @(t) (Ah + Bh*t).*exp(s*t) + xp(t);
end
t = linspace(0, t_end, points);
xt = x(t);
% (mechmat integrates (2) by DOP853 beside this closed form and shows its error)
% T = 1 at r = sqrt(2) for every damping, eq. (6): found by fzero
Tr = @(r) sqrt((1 + (2*zeta*r)^2)/((1 - r^2)^2 + (2*zeta*r)^2)) - 1;
if Tr(1.01) > 0
  out.r_crossing = fzero(Tr, [1.01 3]);
end
