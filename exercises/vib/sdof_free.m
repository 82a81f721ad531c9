% Free vibration of a damped oscillator: m x'' + c x' + k x = 0, eq. (1).
omega_n = sqrt(k/m);                      % eq. (2)
zeta = c/(2*sqrt(k*m));
a = zeta*omega_n;                         % decay rate c/(2 m)
out.omega_n = omega_n;
out.zeta = zeta;
out.c_critical = 2*sqrt(k*m);
% the closed form of the regime, eq. (4) and its critical and overdamped forms
if abs(zeta - 1) <= 1e-12                 % critically damped
  regime = 1; omega_d = 0;
  x = @(t) (x0 + (v0 + omega_n*x0)*t).*exp(-omega_n*t);
  v = @(t) ((v0 + omega_n*x0) - omega_n*(x0 + (v0 + omega_n*x0)*t)).*exp(-omega_n*t);
elseif zeta < 1                           % underdamped
  regime = 0; omega_d = omega_n*sqrt(1 - zeta^2);
  B = (v0 + a*x0)/omega_d;
  x = @(t) exp(-a*t).*(x0*cos(omega_d*t) + B*sin(omega_d*t));
  v = @(t) exp(-a*t).*((B*omega_d - a*x0)*cos(omega_d*t) - (x0*omega_d + a*B)*sin(omega_d*t));
  out.T_d = 2*pi/omega_d;
  out.log_decrement = 2*pi*zeta/sqrt(1 - zeta^2);
else                                      % overdamped: two real roots, eq. (3)
  regime = 2; omega_d = 0;
  s2 = -(a + omega_n*sqrt((zeta - 1)*(zeta + 1)));
  s1 = omega_n^2/s2;                      % s1 s2 = omega_n^2: -a + omega_n sqrt(zeta^2 - 1) would cancel
  C1 = (v0 - s2*x0)/(s1 - s2); C2 = x0 - C1;
  x = @(t) C1*exp(s1*t) + C2*exp(s2*t);
  v = @(t) C1*s1*exp(s1*t) + C2*s2*exp(s2*t);
end
out.omega_d = omega_d;
out.regime = regime;
t = linspace(0, t_end, points);
xt = x(t);                                % the plotted response
% energy, eq. (5): what the damper took is what the block lost
E = @(x, v) 0.5*m*v.^2 + 0.5*k*x.^2;
out.energy_dissipated = E(x0, v0) - E(x(t_end), v(t_end));
% (mechmat integrates (1) by DOP853 beside this closed form and shows its error)
