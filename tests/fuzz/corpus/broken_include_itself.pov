// A file that includes itself stops at the include depth limit
// (--max-include-depth N).

