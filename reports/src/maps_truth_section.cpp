namespace rotlie::reports {}
