namespace contactlab {}
