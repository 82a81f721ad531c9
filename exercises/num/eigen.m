% num-eigen: K v = lambda M v by MATLAB's eig(K, M); lambda = omega^2
% gives the natural frequencies, v the mode shapes (eqs. 1-4).
[V, D] = eig(K, M);
[lambda, order] = sort(diag(D));
V = V(:, order);
for j = 1:size(V, 2)
    V(:, j) = V(:, j) / sqrt(V(:, j)' * M * V(:, j));   % M-normalised, eq. (4)
    k = find(abs(V(:, j)) > 1e-8 * max(abs(V(:, j))), 1);
    if V(k, j) < 0                                       % first clear component positive
        V(:, j) = -V(:, j);
    end
end
omega = sqrt(lambda);                        % rad/s, eq. (2); imaginary when lambda < 0
f = omega / (2 * pi);                        % Hz
out.lambda_min = lambda(1);
out.lambda_max = lambda(end);
out.unstable_modes = sum(lambda < 0);
out.cond_M = cond(M);
