% Rolling or sliding, eqs. (2)-(3).
h = sqrt(r^2 - a^2);
out.P_roll = W * a / (h * cos(theta) + a * sin(theta));
out.P_slide = mu * W / (cos(theta) + mu * sin(theta));
out.mode = 1 + (out.P_slide < out.P_roll);          % 1 rolls first, 2 slides first
out.P_approx = W * a / r;
out.mu_boundary = out.P_roll * cos(theta) / (W - out.P_roll * sin(theta));
% eq. (4): unknowns [P; N; F] at the rolling limit
x = [cos(theta) 0 -1; sin(theta) 1 0; 0 a -h] \ [0; W; 0];
fprintf('rolling limit: P = %.10g N, N = %.10g N, F = %.10g N (mu N = %.10g N)\n', x(1), x(2), x(3), mu * x(2));
