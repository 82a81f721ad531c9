% Motion about a fixed point in polar coordinates: r(t) and theta(t) given,
% velocity (2) and acceleration (3) in radial and transverse components.
r = r0 + u*t + 0.5*b*t^2;       rd = u + b*t;              rdd = b;
th = theta0 + omega0*t + 0.5*alpha*t^2;  thd = omega0 + alpha*t;  thdd = alpha;
out.r = r;
out.theta = th;
out.v_r = rd;                          % (2)
out.v_theta = r*thd;
out.v = sqrt(out.v_r^2 + out.v_theta^2);
out.a_centripetal = -r*thd^2;          % (3)
out.a_coriolis = 2*rd*thd;
out.a_r = rdd + out.a_centripetal;
out.a_theta = r*thdd + out.a_coriolis;
out.a = sqrt(out.a_r^2 + out.a_theta^2);
% the same in x, y, and the path's tangential and normal components
er = [cos(th); sin(th)];  et = [-sin(th); cos(th)];
v = out.v_r*er + out.v_theta*et;
a = out.a_r*er + out.a_theta*et;
if out.v > 0
  out.a_t = dot(v, a) / out.v;
  out.a_n = abs(v(1)*a(2) - v(2)*a(1)) / out.v;
  if out.a_n > 0
    out.rho = out.v^2 / out.a_n;
  end
end
% a check by central differences of x(t) = r cos(theta), y(t) = r sin(theta)
pos = @(s) (r0 + u*s + 0.5*b*s^2) * [cos(theta0 + omega0*s + 0.5*alpha*s^2); sin(theta0 + omega0*s + 0.5*alpha*s^2)];
h = 1e-4;
v_fd = (pos(t + h) - pos(t - h)) / (2*h);
fprintf('|v - central difference| = %.3g m/s (about h^2 = %.0e times the third derivative)\n', norm(v - v_fd), h^2);
