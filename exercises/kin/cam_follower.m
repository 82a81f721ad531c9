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
sc = @(b) [1, 1/b, 1/b^2, 1/b^3];          % d/dtheta = (1/beta) d/du
motion = @(th) ...
  (th < beta_rise) * (h * L(th/beta_rise) .* sc(beta_rise)) + ...
  (th >= beta_rise & th < beta_rise + beta_dwell) * [h 0 0 0] + ...
  (th >= beta_rise + beta_dwell & th < beta_rise + beta_dwell + beta_return) * ...
     ([h 0 0 0] - h * L(min(max((th - beta_rise - beta_dwell)/beta_return, 0), 1)) .* sc(beta_return));
th = mod(theta, 2*pi);
d = motion(th);                            % s, s', s'', s''' by the cam angle
out.s = d(1);
out.v = omega * d(2);
out.a = omega^2 * d(3);
out.jerk = omega^3 * d(4);
out.pressure_angle = atan2(d(2) - e, s0 + d(1));          % (2)
out.v_max = abs(omega) * pk(1) * h / min(beta_rise, beta_return);
out.a_max = omega^2 * pk(2) * h / min(beta_rise, beta_return)^2;
% radius of curvature of the pitch curve (3) on a fine grid of the turn
rho = @(d) -((s0 + d(1))^2 + (d(2) - e)^2)^1.5 / ((s0 + d(1))*(d(3) - s0 - d(1)) - (d(2) - e)*(2*d(2) - e));
rmin = Inf;
for k = 0:3599
  dk = motion(2*pi*k/3600);
  rk = rho(dk);
  if rk > 0 && rk < rmin
    rmin = rk;
  end
end
out.rho_pitch_min = rmin;
out.rho_cam_min = rmin - Rr;               % (4): negative means undercut
out.undercut = rmin < Rr;
