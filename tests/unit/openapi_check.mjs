// openapi_check.mjs — validate an OpenAPI document with an established
// validator (@seriousme/openapi-schema-validator, from the lock file);
// exit status 0 when it is valid. Used by test_http_cache.c.
import { Validator } from '@seriousme/openapi-schema-validator';

const file = process.argv[2];
const validator = new Validator();
const res = await validator.validate(file);
if (!res.valid) {
  console.error(`openapi_check: ${file} is not a valid OpenAPI ${validator.version ?? ''} document`);
  console.error(JSON.stringify(res.errors, null, 1).slice(0, 4000));
  process.exit(1);
}
console.log(`openapi_check: valid OpenAPI ${validator.version}`);
