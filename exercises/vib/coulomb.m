% Coulomb friction: m x'' + k x = -mu m g sign(x'), eq. (1): arc by arc.
omega_n = sqrt(k/m);
d = mu*m*g/k;                             % friction band: the centre shift of each arc
out.omega_n = omega_n;
out.friction_band = d;
out.decay_per_cycle = 4*d;
out.friction_limit = mu*m*g;
% the exact piecewise solution, eqs. (3)-(6): each arc is half a cosine
% about +-d; from rest at x it ends at -(x - 2 d sign x), eq. (4), so after
% j arcs |x| has lost 2 j d: computed that way, not arc by arc, so that a
% long decay keeps its last digits
sticks = @(x) abs(k*x) <= mu*m*g*(1 + 1e-9);           % eq. (6)
if v0 == 0 && sticks(x0)
  t = 0; x = x0; arcs = 0;                  % static friction holds from the start
else
  if v0 ~= 0                                % the first arc from a moving start
    s = sign(v0); cs = -s*d;
    R = hypot(x0 - cs, v0/omega_n);
    % the velocity first vanishes where tan(omega_n t) = v0/(omega_n (x0 - cs)),
    % omega_n t in (0, pi)
    t1 = atan2(s*v0/omega_n, s*(x0 - cs))/omega_n;
    x1 = cs + s*R; base = abs(x1); side = sign(x1); lost = 0;
  else                                      % from rest: the first arc is a half period
    t1 = pi/omega_n; base = abs(x0); side = -sign(x0); lost = 1;
  end
  arcs = 1; x = side*(base - 2*lost*d);
  while ~sticks(x)
    arcs = arcs + 1; lost = lost + 1; side = -side;
    x = side*(base - 2*lost*d);
  end
  t = t1 + (arcs - 1)*pi/omega_n;
end
out.stop_time = t;
out.x_final = x;
out.half_cycles = arcs;
out.spring_force_final = abs(k*x);
% (mechmat integrates each arc by DOP853, stopped at the velocity zero as an
% event, beside this exact solution)
