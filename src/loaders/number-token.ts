// Is a token a decimal number as MTL and OBJ files write them ("1", "-0.5", ".5", "3.", "1e-5")?
// The pattern has one way to match each digit: the former /\d+\.?\d*/ could split a run of
// digits between its two \d's in n ways, and on a token that failed at its end (40,000 digits
// then a letter) backtracked for seconds. Tokens longer than any number are refused outright.
const NUMBER = /^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/;
const LONGEST = 64;

export function isNumberToken(token: string): boolean {
  return token.length <= LONGEST && NUMBER.test(token);
}
