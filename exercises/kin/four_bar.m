% Four-bar linkage: the loop closure (1) solved by Newton-Raphson at theta2,
% then angular velocities (4) and accelerations (5) from the Jacobian.
% Unknowns q = [theta3; theta4]; O2 = (0,0), O4 = (d,0).
Phi = @(q) [a*cos(theta2) + b*cos(q(1)) - c*cos(q(2)) - d;
            a*sin(theta2) + b*sin(q(1)) - c*sin(q(2))];
J = @(q) [-b*sin(q(1)),  c*sin(q(2));
           b*cos(q(1)), -c*cos(q(2))];
% the assembly: C where the circles about B (radius b) and O4 (radius c) meet,
% left of the line from B to O4 for 'open', right of it for 'crossed'
B = a*[cos(theta2); sin(theta2)];
u = [d; 0] - B;  e = norm(u);  u = u / e;
along = (b^2 + e^2 - c^2) / (2*e);
h = sqrt(b^2 - along^2);
if strcmp(branch, 'open'), s = 1; else, s = -1; end
C = B + along*u + s*h*[-u(2); u(1)];
q = [atan2(C(2) - B(2), C(1) - B(1)); atan2(C(2), C(1) - d)];
q = q + [0.05; -0.05];                 % a little off, so that Newton has work to do
for k = 1:50
  dq = -J(q) \ Phi(q);
  q = q + dq;
  if norm(dq) < 1e-13
    break
  end
end
out.theta3 = atan2(sin(q(1)), cos(q(1)));
out.theta4 = atan2(sin(q(2)), cos(q(2)));
% velocities (4): J q' = nu, nu = -dPhi/dtheta2, times omega2
nu = [a*sin(theta2); -a*cos(theta2)];
w = J(q) \ nu;
out.omega3 = omega2 * w(1);
out.omega4 = omega2 * w(2);
% accelerations (5)
gam = [a*cos(theta2) + b*cos(q(1))*w(1)^2 - c*cos(q(2))*w(2)^2;
       a*sin(theta2) + b*sin(q(1))*w(1)^2 - c*sin(q(2))*w(2)^2];
al = J(q) \ gam;
out.alpha3 = omega2^2 * al(1);
out.alpha4 = omega2^2 * al(2);
% Freudenstein's equation (2) for theta4, by t = tan(theta4/2)
K1 = d/a;  K2 = d/c;  K3 = (a^2 - b^2 + c^2 + d^2) / (2*a*c);
A = cos(theta2) - K1 - K2*cos(theta2) + K3;
Bq = -2*sin(theta2);
Cq = K1 - (K2 + 1)*cos(theta2) + K3;
t4 = 2*atan2(-Bq + [-1 1]*sqrt(Bq^2 - 4*A*Cq), 2*A);
fprintf('theta4 by Newton %.15g; the two roots of Freudenstein: %.15g %.15g\n', out.theta4, t4);
% Grashof: shortest + longest <= the other two
L = sort([a b c d]);
out.grashof = L(1) + L(4) <= L(2) + L(3) + 4*eps*sum(L);
% transmission angle (6), between coupler and rocker, by the law of cosines
e2 = a^2 + d^2 - 2*a*d*cos(theta2);
out.mu = acos((b^2 + c^2 - e2) / (2*b*c));
