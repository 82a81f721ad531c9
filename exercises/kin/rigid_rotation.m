% Rotation about a fixed axis through O (direction axis), plus a translation
% of the axis at v_axis: position (1), velocity (2), acceleration (3) of P.
u = axis(:) / norm(axis);
th = omega*t + 0.5*alpha*t^2;              % angle turned
w = omega + alpha*t;                       % angular velocity now
K = [0 -u(3) u(2); u(3) 0 -u(1); -u(2) u(1) 0];
R = eye(3) + sin(th)*K + (1 - cos(th))*K*K;   % Rodrigues' formula
r = R * point(:);                          % P from O, eq. (1)
v = v_axis(:) + cross(w*u, r);             % (2)
a = alpha*cross(u, r) + cross(w*u, cross(w*u, r));   % (3)
out.theta = th;
out.omega_t = w;
out.rho = norm(r - u*dot(r, u));           % distance from the axis
out.vx = v(1);  out.vy = v(2);  out.vz = v(3);
out.v = norm(v);
out.ax = a(1);  out.ay = a(2);  out.az = a(3);
out.a = norm(a);
out.a_t = alpha * out.rho;
out.a_n = w^2 * out.rho;
fprintf('|v - v_axis| = %.15g, |omega| rho = %.15g\n', norm(v - v_axis(:)), abs(w)*out.rho);
