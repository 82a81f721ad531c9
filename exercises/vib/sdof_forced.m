% Forced vibration of a damped oscillator: m x'' + c x' + k x = F0 cos(omega t), eq. (1).
omega_n = sqrt(k/m);
zeta = c/(2*sqrt(k*m));
D = k - m*omega^2 + 1i*c*omega;           % dynamic stiffness, eq. (3)
X = F0/abs(D);                            % steady amplitude, eq. (4)
phase = angle(D);                         % lag of x behind the force, in [0, pi]
out.omega_n = omega_n;
out.zeta = zeta;
out.X = X;
out.phase = phase;
out.magnification = k/abs(D);
out.r = omega/omega_n;
if abs(zeta - 1) <= 1e-12
  out.regime = 1;
elseif zeta < 1
  out.regime = 0;
else
  out.regime = 2;
end
% the closed form: steady state plus the free motion that meets x0, v0
% (roots s1, s2 of m s^2 + c s + k = 0; complex when underdamped)
xp = @(t) X*cos(omega*t - phase);
vp = @(t) -X*omega*sin(omega*t - phase);
s12 = roots([m c k]);
if abs(s12(1) - s12(2)) > 1e-9*omega_n
  C = [1 1; s12(1) s12(2)] \ [x0 - xp(0); v0 - vp(0)];
  x = @(t) real(C(1)*exp(s12(1)*t) + C(2)*exp(s12(2)*t)) + xp(t);
else                                      % a double root: (A + B t) e^(s t)
  s = real(s12(1)); A = x0 - xp(0); B = v0 - vp(0) - s*A;
  x = @(t) (A + B*t).*exp(s*t) + xp(t);
end
t = linspace(0, t_end, points);
xt = x(t);                                % the plotted response
% (mechmat integrates (1) by DOP853 beside this closed form, and measures X and
% the phase on a run started on the steady orbit)
