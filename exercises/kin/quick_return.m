% Quick return (crank and slotted lever): the loop closure (1) in
% q = [theta4; s; X; s2] by Newton-Raphson, velocities and accelerations
% by the Jacobian, against the closed form (2); stroke and time ratio (3).
Phi = @(q) [q(2)*cos(q(1)) - r*cos(theta2);
            q(2)*sin(q(1)) - d - r*sin(theta2);
            q(4)*cos(q(1)) - q(3);
            q(4)*sin(q(1)) - H];
J = @(q) [-q(2)*sin(q(1)), cos(q(1)),  0, 0;
           q(2)*cos(q(1)), sin(q(1)),  0, 0;
          -q(4)*sin(q(1)), 0,         -1, cos(q(1));
           q(4)*cos(q(1)), 0,          0, sin(q(1))];
q = [pi/2; d; 0; H];                      % a rough guess: the lever upright
for k = 1:50
  dq = -J(q) \ Phi(q);
  q = q + dq;
  if norm(dq) < 1e-13 * (1 + norm(q))
    break
  end
end
nu = [-r*sin(theta2); r*cos(theta2); 0; 0];
qd = J(q) \ nu;                           % per unit crank speed
w = qd(1);
gam = [ 2*qd(2)*sin(q(1))*w + q(2)*cos(q(1))*w^2 - r*cos(theta2);
       -2*qd(2)*cos(q(1))*w + q(2)*sin(q(1))*w^2 - r*sin(theta2);
        2*qd(4)*sin(q(1))*w + q(4)*cos(q(1))*w^2;
       -2*qd(4)*cos(q(1))*w + q(4)*sin(q(1))*w^2];
qdd = J(q) \ gam;
out.theta4 = q(1);
out.omega4 = omega * qd(1);
out.alpha4 = omega^2 * qdd(1);
out.x_ram = q(3);
out.v_ram = omega * qd(3);
out.a_ram = omega^2 * qdd(3);
fprintf('x_ram by Newton %.15g, closed form (2) %.15g\n', q(3), H*r*cos(theta2)/(d + r*sin(theta2)));
% dead centres: the lever tangent to the crank circle, sin(theta2) = -r/d
al = asin(r/d);
out.theta2_dead1 = -al;
out.theta2_dead2 = pi + al;
out.stroke = 2*H*r / sqrt(d^2 - r^2);
out.time_ratio = (pi + 2*al) / (pi - 2*al);     % (3)
out.v_cut_avg = out.stroke * abs(omega) / (pi + 2*al);
out.v_return_avg = out.stroke * abs(omega) / (pi - 2*al);
