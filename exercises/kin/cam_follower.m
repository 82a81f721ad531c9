% Cam and roller follower: the motion law (1) over rise, dwell, return and
% dwell; velocity, acceleration, jerk; pressure angle (2); pitch curve
% radius of curvature (3) and the profile's (4).
s0 = sqrt((Rb + Rr)^2 - e^2);              % roller centre's height at zero lift
% the law of a unit rise over u in [0, 1]: value and three derivatives by u
switch law
  case 'cycloidal'
    L = @(u) [u - sin(2*pi*u)/(2*pi), 1 - cos(2*pi*u), 2*pi*sin(2*pi*u), 4*pi^2*cos(2*pi*u)];
    pk = [2, 2*pi];
  case 'harmonic'
    L = @(u) [(1 - cos(pi*u))/2, pi/2*sin(pi*u), pi^2/2*cos(pi*u), -pi^3/2*sin(pi*u)];
    pk = [pi/2, pi^2/2];
  case 'polynomial345'
    L = @(u) [10*u^3 - 15*u^4 + 6*u^5, 30*u^2 - 60*u^3 + 30*u^4, 60*u - 180*u^2 + 120*u^3, 60 - 360*u + 360*u^2];
    pk = [1.875, 10*sqrt(3)/3];
  otherwise
    L = @(u) (u < 0.5) * [2*u^2, 4*u, 4, 0] + (u >= 0.5) * [1 - 2*(1 - u)^2, 4*(1 - u), -4, 0];
    pk = [2, 4];
end
b1 = beta_rise;  b2 = b1 + beta_dwell;  b3 = b2 + beta_return;
sc = @(b) [1, 1/b, 1/b^2, 1/b^3];          % d/dtheta = (1/beta) d/du
% s, s', s'', s''' at a cam angle th in [0, 2 pi)
motion = @(th) (th < b1) * (h * L(th/b1) .* sc(b1)) + (th >= b1 & th < b2) * [h 0 0 0] + ...
  (th >= b2 & th < b3) * ([h 0 0 0] - h * L(min(max((th - b2)/beta_return, 0), 1)) .* sc(beta_return));
d = motion(theta - 2*pi*floor(theta/(2*pi)));
out.s = d(1);
out.v = omega * d(2);
out.a = omega^2 * d(3);
out.jerk = omega^3 * d(4);
out.pressure_angle = atan2(d(2) - e, s0 + d(1));          % (2)
out.v_max = abs(omega) * pk(1) * h / min(beta_rise, beta_return);
out.a_max = omega^2 * pk(2) * h / min(beta_rise, beta_return)^2;
% the pitch curve's radius of curvature (3): + where convex
rho = @(d) -((s0 + d(1))^2 + (d(2) - e)^2)^1.5 / ((s0 + d(1))*(d(3) - s0 - d(1)) - (d(2) - e)*(2*d(2) - e));
% the extremes: a scan of the turn, then golden section between the best
% sample's neighbours (and, for rho, both sides of the law's jumps)
pa = @(d) abs(atan2(d(2) - e, s0 + d(1)));
fphi = @(th) pa(motion(th));
frho = @(th) 1 ./ max(1 ./ rho(motion(th)), 0);   % rho where convex, else +Inf
g = (sqrt(5) - 1) / 2;
for which = 1:2
  if which == 1, f = @(th) -fphi(th); else, f = frho; end   % minimise f
  fb = Inf;  kb = 0;
  for k = 0:3599
    fk = f(2*pi*k/3600);
    if fk < fb, fb = fk; kb = k; end
  end
  lo = 2*pi*(kb - 1)/3600;  hi = 2*pi*(kb + 1)/3600;
  for it = 1:60                            % golden section
    x1 = hi - g*(hi - lo);  x2 = lo + g*(hi - lo);
    if f(x1) < f(x2), hi = x2; else, lo = x1; end
  end
  fb = min(fb, f((lo + hi)/2));
  if which == 2
    for jt = [0 b1 b2 b3 2*pi b1/2 b2 + beta_return/2]
      fb = min([fb, f(jt - 1e-9), f(jt + 1e-9)]);
    end
    out.rho_pitch_min = fb;
    out.rho_cam_min = fb - Rr;             % (4): negative means undercut
    out.undercut = fb < Rr;
  else
    out.pressure_angle_max = -fb;
  end
end
