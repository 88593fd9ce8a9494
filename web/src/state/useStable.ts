// A callback whose identity never changes but which always calls the latest `fn`: memoised
// panels and nodes that receive it are not redrawn because their parent drew again.

import { useCallback, useEffect, useRef } from "react";

export function useStable<A extends unknown[], R>(fn: (...args: A) => R): (...args: A) => R {
  const latest = useRef(fn);
  useEffect(() => {
    latest.current = fn;
  }, [fn]);
  return useCallback((...args: A) => latest.current(...args), []);
}
