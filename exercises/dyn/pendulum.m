% The pendulum at large amplitude: theta'' + (g/L) sin(theta) = 0.
wn = sqrt(g / L);                         % small-angle frequency
out.omega_n = wn;
out.period_small = 2 * pi / wn;           % eq. (2)

% the modulus k from the energy, eq. (3); kc = sqrt(1 - k^2) computed directly
s = sin(theta0 / 2);
c = cos(theta0 / 2);
if theta0 == pi
  c = 0;                                  % the top exactly
end
a = abs(omega0) / (2 * wn);
kc2 = (c - a) * (c + a);
if kc2 > 0
  out.motion = 0;                         % swinging
  k = sqrt(s^2 + a^2);  kc = sqrt(kc2);
  out.k = k;
  out.theta_max = 2 * asin(k);
elseif kc2 == 0
  out.motion = 1;                         % the separatrix: infinite period
  out.k = 1;
else
  out.motion = 2;                         % over the top
  kk = sqrt(s^2 + a^2);  kc = sqrt(-kc2) / kk;
  out.k = kk;
end

% K by the arithmetic-geometric mean: K = pi / (2 AGM(1, kc)), eq. (5)
if out.motion ~= 1
  x = 1;  y = kc;
  while x - y > eps * x
    z = (x + y) / 2;  y = sqrt(x * y);  x = z;
  end
  K = pi / (x + y);
  if out.motion == 0
    out.period = 4 * K / wn;              % eq. (5)
  else
    out.period = 2 * K / (kk * wn);       % eq. (7): one turn
  end
  out.period_ratio = out.period / out.period_small;
else
  disp('theta0 = pi at rest is the separatrix: the period is infinite');
end

% the amplitude with a 1 % longer period: bisection on 2 K(sin(th/2)) / pi = 1.01
lo = 0.1;  hi = 1.0;
while hi - lo > 4 * eps
  th = (lo + hi) / 2;
  x = 1;  y = cos(th / 2);
  while x - y > eps * x
    z = (x + y) / 2;  y = sqrt(x * y);  x = z;
  end
  if 2 * (pi / (x + y)) / pi > 1.01
    hi = th;
  else
    lo = th;
  end
end
out.theta_1pct = (lo + hi) / 2;

% the motion by ode45 over one period: the bob must come back to its start
if isfield(out, 'period')
  opts = odeset('RelTol', 1e-10, 'AbsTol', 1e-12);
  [t, y] = ode45(@(t, y) [y(2); -wn^2 * sin(y(1))], [0 out.period / 2 out.period], [theta0; omega0], opts);
  fprintf('after one period ode45 is back within %.3g rad and %.3g rad/s\n', ...
          abs(mod(y(end, 1) - theta0 + pi, 2*pi) - pi), abs(y(end, 2) - omega0));
end
