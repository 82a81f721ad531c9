% Resonance: m x'' + c x' + k x = F0 cos(omega t) from rest, omega = omega_n (1 + detuning), eq. (1).
omega_n = sqrt(k/m);
omega = omega_n*(1 + detuning);
zeta = c/(2*sqrt(k*m));
out.omega_n = omega_n;
out.omega = omega;
out.zeta = zeta;
out.growth_rate_theory = F0/(2*m*omega_n);
% k - m omega^2 from the detuning itself: no digits lost at detuning = 1e-12
D = -k*detuning*(2 + detuning) + 1i*c*omega;
if abs(D) > 0
  out.X = F0/abs(D);
  out.magnification = k/abs(D);
else
  out.X = 0;                                % none: tuned and undamped, the amplitude grows without bound
end
if zeta > 0
  out.tau = 1/(zeta*omega_n);
end
if detuning ~= 0
  out.beat_period = 2*pi/(omega_n*abs(detuning));
end
% the closed form x(t)
if c == 0
  % eq. (2) as a product, eq. (4): exact at and near resonance, where it is eq. (3)
  s = (omega_n + omega)/2; d = (omega_n - omega)/2;
  sinc0 = @(u) (u == 0) + (u ~= 0).*sin(u)./(u + (u == 0));   % sin(u)/u, 1 at u = 0
  x = @(t) F0/m*t.*sin(s*t).*sinc0(d*t)/(2*s);
else                                        % damped: steady state plus the free motion from rest
  A = F0/D; s12 = roots([m c k]);
  xp = @(t) real(A*exp(1i*omega*t)); vp = @(t) real(1i*omega*A*exp(1i*omega*t));
  if abs(s12(1) - s12(2)) > 1e-9*omega_n
    C = [1 1; s12(1) s12(2)] \ [-xp(0); -vp(0)];
    x = @(t) real(C(1)*exp(s12(1)*t) + C(2)*exp(s12(2)*t)) + xp(t);
  else
    sr = real(s12(1)); Ah = -xp(0); Bh = -vp(0) - sr*Ah;
    x = @(t) (Ah + Bh*t).*exp(sr*t) + xp(t);
  end
end
t = linspace(0, t_end, points);
xt = x(t);                                  % the plotted response
% (mechmat integrates (1) by DOP853 beside this closed form and shows its error)
% the amplitude over the last two periods: projection on cos and sin
T = 2*pi/omega;
if t_end >= 2*T
  i = 0:127;
  out.amplitude_final = 2/128*abs(sum(x(t_end - 2*T + T*i/64).*exp(-2i*pi*i/64)));
end
