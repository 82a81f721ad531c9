% The friction circle, eqs. (1)-(3).
out.phi = atan(mu);
out.r_f = r * sin(out.phi);
out.T_raise = W * (R + out.r_f) / (R - out.r_f);
out.T_lower = W * (R - out.r_f) / (R + out.r_f);
out.M_f = (out.T_raise + W) * out.r_f;
out.efficiency = W / out.T_raise;
out.r_f_approx = mu * r;
% The contact equations (4) by Newton's method: x = [N; theta; T], raising.
x = [2 * W; 0; W];
for it = 1:20
  N = x(1);  c = cos(x(2));  s = sin(x(2));
  f = [-N * s + mu * N * c; N * c + mu * N * s - x(3) - W; W * R - x(3) * R + mu * N * r];
  J = [-s + mu * c, -N * c - mu * N * s, 0; c + mu * s, -N * s + mu * N * c, -1; mu * r, 0, -R];
  x = x - J \ f;
end
fprintf('contact angle %.15g rad (phi = %.15g), T = %.15g N\n', x(2), out.phi, x(3));
