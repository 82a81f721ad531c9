% num-linear-system: A x = b by MATLAB's backslash (LU with partial
% pivoting), and the condition number that says how many digits of x a
% double-precision solve keeps (eqs. 4-6).
x = A \ b(:);
s = svd(A);                                  % singular values, largest first
for i = 1:numel(x)
    out.(sprintf('x%d', i)) = x(i);
end
out.cond = s(1) / s(end);                    % eq. (5)
r = b(:) - A * x;                            % the residual, eq. (3)
out.residual = norm(r);
out.backward_error = norm(r) / (s(1) * norm(x) + norm(b));   % eq. (4)
out.digits = max(0, min(16, floor(-log10(out.cond * eps))));
