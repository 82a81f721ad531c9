% num-complex: one operation on complex numbers, in rectangular form
% (eqs. 4-5), with the result also in polar form (eqs. 1-3).
a = a_re + 1i * a_im;
b = b_re + 1i * b_im;
switch op
    case 'square'
        z = a * a;                           % (2+i)^2 = 3+4i
    case 'multiply'
        z = a * b;                           % moduli multiply, arguments add (eq. 6)
    case 'divide'
        z = a / b;                           % a conj(b) / |b|^2 (eq. 5)
    case 'power'
        z = 1;                               % a^n by repeated multiplication
        for j = 1:abs(n)
            z = z * a;
        end
        if n < 0
            z = 1 / z;
        end
    case 'roots'
        k = 0:n-1;                           % all n roots, de Moivre (eq. 8)
        w = abs(a)^(1/n) * exp(1i * (angle(a) + 2*pi*k) / n);
        z = w(1);                            % the principal root
end
out.re = real(z);
out.im = imag(z);
out.modulus = abs(z);
out.argument = angle(z);                     % in (-pi, pi]
out.a_modulus = abs(a);
out.a_argument = angle(a);
