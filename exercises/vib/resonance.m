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
end
if zeta > 0
  out.tau = 1/(zeta*omega_n);
end
if detuning ~= 0
  out.beat_period = 2*pi/(omega_n*abs(detuning));
end
t = linspace(0, t_end, points);
if c == 0 && detuning == 0
  xt = F0*t.*sin(omega*t)/(2*m*omega);     % eq. (3): linear growth
elseif c == 0
  % eq. (2) as a product, eq. (4): no cancellation near resonance
  s = (omega_n + omega)/2; d = (omega_n - omega)/2;
  sinc0 = @(u) (u == 0) + (u ~= 0).*sin(u)./(u + (u == 0));   % sin(u)/u, 1 at u = 0
  xt = F0/m*t.*sin(s*t).*sinc0(d*t)/(2*s);
else                                        % damped: steady state plus the free motion from rest
  A = F0/D; s12 = roots([m c k]);
  xp = @(t) real(A*exp(1i*omega*t)); vp = @(t) real(1i*omega*A*exp(1i*omega*t));
  if abs(s12(1) - s12(2)) > 1e-9*omega_n
    C = [1 1; s12(1) s12(2)] \ [-xp(0); -vp(0)];
    xt = real(C(1)*exp(s12(1)*t) + C(2)*exp(s12(2)*t)) + xp(t);
  else
    s = real(s12(1)); Ah = -xp(0); Bh = -vp(0) - s*Ah;
    xt = (Ah + Bh*t).*exp(s*t) + xp(t);
  end
end
[~, y] = ode45(@(t, y) [y(2); (F0*cos(omega*t) - c*y(2) - k*y(1))/m], t, [0; 0], ...
               odeset('RelTol', 1e-10, 'AbsTol', 1e-12*max(abs(xt))));
out.max_error_dop853 = max(abs(y(:, 1)' - xt));
