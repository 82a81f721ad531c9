% Euler angles: the rotation matrix (1), the angular velocity from the
% rates (2), the angles read back from R, and gimbal lock.
Rx = @(a) [1 0 0; 0 cos(a) -sin(a); 0 sin(a) cos(a)];
Ry = @(a) [cos(a) 0 sin(a); 0 1 0; -sin(a) 0 cos(a)];
Rz = @(a) [cos(a) -sin(a) 0; sin(a) cos(a) 0; 0 0 1];
E = eye(3);
switch sequence
  case 'zyx', R1 = Rz(phi); R2 = Ry(theta); R3 = Rx(psi); ax = [3 2 1];
  case 'zyz', R1 = Rz(phi); R2 = Ry(theta); R3 = Rz(psi); ax = [3 2 3];
  case 'zxz', R1 = Rz(phi); R2 = Rx(theta); R3 = Rz(psi); ax = [3 1 3];
  otherwise,  R1 = Rx(phi); R2 = Ry(theta); R3 = Rz(psi); ax = [1 2 3];
end
R = R1 * R2 * R3;                              % (1): each turn about the axis as turned
% (2): omega = phi' e_i + theta' R1 e_j + psi' R1 R2 e_k  (space components)
B = [E(:, ax(1)), R1*E(:, ax(2)), R1*R2*E(:, ax(3))];
w = B * [phi_dot; theta_dot; psi_dot];
wb = R' * w;                                   % body components
out.omega_x = w(1);  out.omega_y = w(2);  out.omega_z = w(3);  out.omega = norm(w);
out.omega_body_x = wb(1);  out.omega_body_y = wb(2);  out.omega_body_z = wb(3);
% the angular acceleration at constant rates: the 2nd and 3rd axes turn
w1 = phi_dot * B(:,1);
al = theta_dot * cross(w1, B(:,2)) + psi_dot * cross(w1 + theta_dot*B(:,2), B(:,3));
out.alpha_x = al(1);  out.alpha_y = al(2);  out.alpha_z = al(3);
out.det_B = det(B);                            % +-cos(theta) or +-sin(theta)
% the single turn equal to R: sin from its skew part, cos from its trace
out.rotation_angle = atan2(norm([R(3,2) - R(2,3), R(1,3) - R(3,1), R(2,1) - R(1,2)]) / 2, (trace(R) - 1) / 2);
out.v_P = norm(cross(w, R*point(:)));
% read the angles back (away from the lock)
if ax(1) == ax(3)
  out.gimbal_lock = abs(sin(theta)) < 1e-8;    % proper Euler: theta = 0 or pi
  lock = 0;
else
  out.gimbal_lock = abs(cos(theta)) < 1e-8;    % Tait-Bryan: theta = +-pi/2
  lock = pi/2;
end
% the first lock the motion meets: theta(t) = lock + k pi
if theta_dot ~= 0
  k = (theta - lock) / pi;
  if theta_dot > 0, kn = floor(k) + 1; else, kn = ceil(k) - 1; end
  tl = (lock + pi*kn - theta) / theta_dot;
  if tl <= t_end
    out.t_lock = tl;
  end
end
if strcmp(sequence, 'zyx') && ~out.gimbal_lock
  back = [atan2(R(2,1), R(1,1)), -asin(R(3,1)), atan2(R(3,2), R(3,3))];
  fprintf('angles back from R: %.15g %.15g %.15g\n', back);
end
% dR/dt = [w]x R: check by a central difference of R(t)
W = [0 -w(3) w(2); w(3) 0 -w(1); -w(2) w(1) 0];
fprintf('det R = %.15g, |R''R - I| = %.2g\n', det(R), norm(R'*R - eye(3)));
