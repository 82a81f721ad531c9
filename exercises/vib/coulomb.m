% Coulomb friction: m x'' + k x = -mu m g sign(x'), eq. (1): arc by arc.
omega_n = sqrt(k/m);
d = mu*m*g/k;                             % friction band: the centre shift of each arc
out.omega_n = omega_n;
out.friction_band = d;
out.decay_per_cycle = 4*d;
out.friction_limit = mu*m*g;
% the exact piecewise solution, eqs. (3)-(6): each arc is half a cosine
% about +-d; from rest at x it ends at -(x - 2 d sign x)
t = 0; x = x0; v = v0; arcs = 0;
if v ~= 0                                 % the first arc from a moving start
  s = sign(v); cs = -s*d;
  R = hypot(x - cs, v/omega_n);
  th = atan2(v/omega_n, x - cs);
  if s > 0
    t = th/omega_n;
  else
    t = (th + pi)/omega_n;
  end
  x = cs + s*R; v = 0; arcs = 1;
end
while abs(k*x) > mu*m*g*(1 + 1e-9)       % eq. (6): the spring beats static friction
  x = -(x - 2*d*sign(x));                 % eq. (4)
  t = t + pi/omega_n;
  arcs = arcs + 1;
end
out.stop_time = t;
out.x_final = x;
out.half_cycles = arcs;
out.spring_force_final = abs(k*x);
% the same with ode45, stopped by an event at each velocity zero
% (value s v, terminal, falling); Octave warns at each stop: silenced
te = 0; y = [x0; v0];
ws = warning('off', 'all');
if v0 == 0 && abs(k*x0) <= mu*m*g*(1 + 1e-9)
  y = [x0; 0];                            % static friction holds from the start
else
  while true
    s = sign(y(2)); if s == 0, s = -sign(y(1)); end
    f = @(t, y) [y(2); -omega_n^2*y(1) - s*mu*g];
    opts = odeset('RelTol', 1e-10, 'AbsTol', 1e-12, 'Events', @(t, y) deal(s*y(2), 1, -1));
    [~, ~, tev, yev] = ode45(f, [te, te + 1.25*pi/omega_n], [y(1); y(2) + s*1e-300], opts);
    te = tev(end); y = [yev(end, 1); 0];
    if abs(k*y(1)) <= mu*m*g*(1 + 1e-9)
      break;
    end
  end
end
warning(ws);
out.stop_time_events = te;
out.x_final_events = y(1);
