// nck serve's HMI (placeholder)
