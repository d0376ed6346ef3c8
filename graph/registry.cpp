namespace papercraft {}
